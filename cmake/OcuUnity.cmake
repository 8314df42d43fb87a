# Unity builds of the console's own libraries (build time, docs/performance.md "Build and test times").
#
# A clean build compiles every library source once; most of a protocol or simulator TU is parsing and
# instantiating the same Boost.Asio, nlohmann-json and standard headers again (those targets have no PCH: a
# 200 MB one cost more to load than it saved). CMake's unity build compiles batches of a target's sources as one
# TU. Only libraries under app/, models/, widgets/, protocols/ and sim/: a test or benchmark is one or two TUs.
# The price: editing one .cpp recompiles its batch (-DOCU_UNITY=OFF for a day of editing one library).
#
# Unity needs every file's internal names to be distinct within its library (no two anonymous-namespace kLog).
# GCC's -Wsubobject-linkage then warns about every Impl that holds an anonymous-namespace type, because the
# .cpp is no longer the main file; in a unity TU that warning says nothing about the code, so it is off there.
#
# Off by default in the sanitizer and fuzz builds (their own build directories, not timed): there every file is
# its own TU again, so a file that leans on its batch neighbours' includes fails to compile there.
if(OCU_SANITIZE OR OCU_FUZZ)
  set(_ocu_unity_default OFF)
else()
  set(_ocu_unity_default ON)
endif()
option(OCU_UNITY "Unity builds of the console's libraries (faster clean builds)" ${_ocu_unity_default})

# Call once at the end of the top CMakeLists.txt, when every target exists (after ocu_apply_pch).
function(ocu_apply_unity)
  if(NOT OCU_UNITY)
    return()
  endif()
  set(n 0)
  ocu_targets_in(${CMAKE_SOURCE_DIR} targets)
  foreach(t IN LISTS targets)
    get_target_property(type ${t} TYPE)
    get_target_property(src ${t} SOURCE_DIR)
    get_target_property(no_unity ${t} OCU_NO_UNITY)
    file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${src})
    if(NOT type MATCHES "^(STATIC_LIBRARY|OBJECT_LIBRARY)$" OR NOT rel MATCHES "^(app|models|widgets|protocols|sim)(/|$)"
       OR no_unity)
      continue()
    endif()
    set_target_properties(${t} PROPERTIES UNITY_BUILD ON)
    target_compile_options(${t} PRIVATE -Wno-subobject-linkage)
    math(EXPR n "${n} + 1")
  endforeach()
  message(STATUS "Unity builds: ${n} libraries (OCU_UNITY)")
endfunction()

