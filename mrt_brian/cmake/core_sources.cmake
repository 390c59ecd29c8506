# The ROS-free core's sources, shared by the package build and the fuzz
# build (fuzz/CMakeLists.txt compiles them again, instrumented).
set(MRT_BRIAN_CORE_SOURCES
  src/behavior_engine.cpp
  src/behavior_list_parser.cpp
  src/brian.cpp
  src/checker.cpp
  src/composer.cpp
  src/config_files.cpp
  src/crisp_input.cpp
  src/defuzzyfier.cpp
  src/expression.cpp
  src/expression_compiler.cpp
  src/fuzzy_set.cpp
  src/fuzzyfier.cpp
  src/legacy.cpp
  src/lexer.cpp
  src/predicate_parser.cpp
  src/rule_behavior.cpp
  src/rule_parser.cpp
  src/shape.cpp
  src/shape_parser.cpp
  src/trace.cpp
  src/validator.cpp)
