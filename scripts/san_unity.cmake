# Included after every project() of the sanitizer builds
# (scripts/sanitize.sh: -DCMAKE_PROJECT_INCLUDE=...). They are CMake unity
# builds (CMAKE_UNITY_BUILD: a target's sources compiled in batches, each
# header parsed once per batch); a target whose sources cannot share a
# translation unit (two files defining the same internal helper) is built
# file by file: its name is in scripts/san_no_unity.txt (known ones) or in
# MRT_SAN_NO_UNITY_FILE (found by sanitize.sh when a unity batch failed).
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
      list(FIND names "${t}" i)  # (not IN_LIST: the packages' policies vary)
      if(NOT i EQUAL -1)
        set_property(TARGET ${t} PROPERTY UNITY_BUILD OFF)
      endif()
    endforeach()
  endfunction()
endif()
cmake_language(DEFER CALL mrt_san_unity_off)
