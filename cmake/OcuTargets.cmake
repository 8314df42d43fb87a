# Helpers shared by every folder's CMakeLists.txt.

# Adds a source folder when its CMakeLists.txt exists (protocol stacks land one by one).
# OCU_SKIP_DIRS (cache list) leaves folders out, for working on one part while others are in flux.
set(OCU_SKIP_DIRS "" CACHE STRING "Source folders to leave out of the build (development aid)")
macro(ocu_optional_subdirectory dir)
  file(RELATIVE_PATH _ocu_rel ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/${dir})
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${dir}/CMakeLists.txt AND NOT _ocu_rel IN_LIST OCU_SKIP_DIRS)
    add_subdirectory(${dir})
  endif()
endmacro()

# Warnings as errors on our own code only (never on third-party headers, which come in as SYSTEM).
function(ocu_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Werror -Wno-error=deprecated-declarations)
endfunction()

# ocu_add_test(NAME n SOURCES s... [LIBS l...] [XVFB] [TIMEOUT sec] [LABELS l...])
# A Qt Test executable registered in CTest. GUI tests run on the offscreen platform with DISPLAY unset;
# XVFB tests (OpenGL/VTK) run under xvfb-run with the xcb platform.
function(ocu_add_test)
  cmake_parse_arguments(T "XVFB;SERIAL" "NAME;TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE Qt6::Test ${T_LIBS})
  ocu_set_warnings(${T_NAME})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 120)
  endif()
  if(T_XVFB)
    add_test(NAME ${T_NAME}
             COMMAND xvfb-run -a -s "-screen 0 1920x1200x24 -nolisten tcp" $<TARGET_FILE:${T_NAME}>)
    set_tests_properties(${T_NAME} PROPERTIES ENVIRONMENT "QT_QPA_PLATFORM=xcb")
  else()
    add_test(NAME ${T_NAME} COMMAND $<TARGET_FILE:${T_NAME}>)
    set_tests_properties(${T_NAME} PROPERTIES ENVIRONMENT "QT_QPA_PLATFORM=offscreen;DISPLAY=")
  endif()
  set_tests_properties(${T_NAME} PROPERTIES TIMEOUT ${T_TIMEOUT} LABELS "${T_LABELS}")
  if(T_SERIAL)
    set_tests_properties(${T_NAME} PROPERTIES RUN_SERIAL TRUE)
  endif()
endfunction()

# ocu_add_bench(NAME n SOURCES s... [LIBS l...]): a Google Benchmark (or harness) executable under bench/.
function(ocu_add_bench)
  cmake_parse_arguments(B "" "NAME" "SOURCES;LIBS" ${ARGN})
  add_executable(${B_NAME} ${B_SOURCES})
  target_link_libraries(${B_NAME} PRIVATE benchmark::benchmark ${B_LIBS})
  ocu_set_warnings(${B_NAME})
endfunction()
