# Included after every project() of the sanitizer builds
# (scripts/sanitize.sh), as -DCMAKE_PROJECT_INCLUDE=... . They are CMake
# unity builds
# (CMAKE_UNITY_BUILD: a target's sources compiled in batches, each header
# parsed once per batch). A target with a single source is compiled as it
# is (nothing to share). A target whose sources cannot share a translation
# unit (two files defining the same internal helper) is built file by file:
# its name is in scripts/san_no_unity.txt (known ones) or in a file of
# MRT_SAN_NO_UNITY_FILES (sanitize.sh adds the ones it finds when a unity
# batch failed). With g++, -Wno-subobject-linkage on the unity targets: a
# source included by the batch is not the main file, so g++ takes a class of
# it holding a type of its own anonymous namespace for one in a header.
if(NOT COMMAND mrt_san_unity_off)
  function(mrt_san_unity_off)
    set(names "")
    foreach(f ${MRT_SAN_NO_UNITY_FILES})
      if(EXISTS "${f}")
        file(STRINGS "${f}" lines REGEX "^[A-Za-z0-9_.+-]+$")
        list(APPEND names ${lines})
      endif()
    endforeach()
    get_property(targets DIRECTORY PROPERTY BUILDSYSTEM_TARGETS)
    foreach(t ${targets})
      get_target_property(type ${t} TYPE)
      get_target_property(unity ${t} UNITY_BUILD)
      if(NOT type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY)$" OR NOT unity)
        continue()
      endif()
      get_target_property(sources ${t} SOURCES)
      set(n 0)
      foreach(s ${sources})
        if(s MATCHES "\\.(c|cc|cpp|cxx)$")
          math(EXPR n "${n} + 1")
        endif()
      endforeach()
      list(FIND names "${t}" i)  # (not IN_LIST: the packages' policies vary)
      if(NOT i EQUAL -1 OR n LESS 2)
        set_property(TARGET ${t} PROPERTY UNITY_BUILD OFF)
      elseif(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        target_compile_options(${t} PRIVATE $<$<COMPILE_LANGUAGE:CXX>:-Wno-subobject-linkage>)
      endif()
    endforeach()
  endfunction()
endif()
cmake_language(DEFER CALL mrt_san_unity_off)
