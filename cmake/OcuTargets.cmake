# Helpers shared by every folder's CMakeLists.txt.

# ocu_protocol_subdirectories(LAYER): the folders of LAYER (STACK, MODELS, WIDGETS, TESTS) of every protocol
# of this build, as the top-level CMakeLists.txt lists them (OCU_PROTOCOL_<p>_<LAYER>, relative to the source
# root; TESTS: tests/<layer>/<p> for each existing layer folder). A listed folder without a CMakeLists.txt is an
# error: a protocol is never left out by accident.
function(ocu_protocol_subdirectories layer)
  foreach(p IN LISTS OCU_PROTOCOLS)
    foreach(dir IN LISTS OCU_PROTOCOL_${p}_${layer})
      if(NOT EXISTS ${CMAKE_SOURCE_DIR}/${dir}/CMakeLists.txt)
        message(FATAL_ERROR "${dir} is listed for the protocol ${p} but has no CMakeLists.txt")
      endif()
      add_subdirectory(${CMAKE_SOURCE_DIR}/${dir} ${CMAKE_BINARY_DIR}/${dir})
    endforeach()
  endforeach()
endfunction()

# Warnings as errors on our own code only (never on third-party headers, which come in as SYSTEM).
function(ocu_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Werror -Wno-error=deprecated-declarations)
endfunction()

# ocu_libraries_in_build(OUT name libs...): OUT is true when every ocu_ library among libs is a target of this
# build; otherwise false, and a status line says which one left `name` out.
function(ocu_libraries_in_build out name)
  foreach(l IN LISTS ARGN)
    if(l MATCHES "^ocu_" AND NOT TARGET ${l})
      message(STATUS "${name} left out: ${l} is not part of this build")
      set(${out} FALSE PARENT_SCOPE)
      return()
    endif()
  endforeach()
  set(${out} TRUE PARENT_SCOPE)
endfunction()

# Test and benchmark executables link without the libraries' debug info: reading and recompressing their line
# tables is three quarters of such a link (test_main_window 1.5 -> 0.35 s CPU, ~160 executables). A failing
# test reports file:line through Qt Test's macros; sanitizer builds and OCU_TEST_DEBUG_INFO=ON keep it for
# symbolised reports and debugger sessions. The console and the simulator always keep theirs.
function(ocu_link_without_debug_info target)
  if(NOT OCU_TEST_DEBUG_INFO AND NOT OCU_SANITIZE AND NOT OCU_FUZZ)
    target_link_options(${target} PRIVATE $<$<CONFIG:RelWithDebInfo>:-Wl,--strip-debug>)
  endif()
endfunction()

# Test code (tests, foreign peers, test servers) at -Og without debug info; the code under test keeps its -O2 -g.
# Their links strip debug info anyway (above), and a failing check reports file:line through Qt Test's macros.
# A sixth less compile time per test TU than -O2 -g (test_main_window.cpp 9.6 -> 8.1 s CPU at -O1, a further
# 10-15 % at -Og -g0), and the precompiled headers stay valid (GCC accepts them across -O1/-Og and -g levels).
# OCU_TEST_DEBUG_INFO=ON keeps -g for debugger sessions. GCC 12 at -Og warns maybe-uninitialized inside
# libstdc++ (std::regex, std::function moves) where nothing is; the code under test keeps that warning at -O2.
function(ocu_compile_as_test_code target)
  target_compile_options(${target} PRIVATE $<$<CONFIG:RelWithDebInfo,Release>:-Og -Wno-maybe-uninitialized>)
  if(NOT OCU_TEST_DEBUG_INFO AND NOT OCU_SANITIZE AND NOT OCU_FUZZ)
    target_compile_options(${target} PRIVATE $<$<CONFIG:RelWithDebInfo,Release>:-g0>)
  endif()
endfunction()

# Test and benchmark executables run moc on their own sources instead of AUTOMOC: AUTOGEN's per-target step
# and the mocs_compilation.cpp it adds cost ~0.75 s of a clean build per target (~170 such targets) for at most
# one moc call. A .cpp with Q_OBJECT includes "<stem>.moc" at its end; a listed header with Q_OBJECT gets
# moc_<stem>.cpp compiled into the target. Include paths and defines are the target's, as AUTOMOC passes them.
# No moc dep file: it would list the .moc that the .cpp includes, a cycle; the classes are in the file itself.
function(ocu_moc_own_sources target)
  set_target_properties(${target} PROPERTIES AUTOMOC OFF)
  get_target_property(srcs ${target} SOURCES)
  set(outdir ${CMAKE_CURRENT_BINARY_DIR}/${target}_moc)
  # Without the target's own moc folder: moc would read an existing <stem>.moc through the .cpp's include of it and
  # name its own output as its dependency, a cycle that stops the next ninja run.
  set(incs "$<FILTER:$<TARGET_PROPERTY:${target},INCLUDE_DIRECTORIES>,EXCLUDE,_moc$>")
  set(defs "$<TARGET_PROPERTY:${target},COMPILE_DEFINITIONS>")
  set(flags "$<$<BOOL:${incs}>:-I$<JOIN:${incs},$<SEMICOLON>-I>>" "$<$<BOOL:${defs}>:-D$<JOIN:${defs},$<SEMICOLON>-D>>")
  set(any FALSE)
  foreach(src IN LISTS srcs)
    cmake_path(ABSOLUTE_PATH src BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} OUTPUT_VARIABLE abs)
    if(NOT abs MATCHES "\\.(cpp|h)$")
      continue()
    endif()
    file(STRINGS ${abs} qobj REGEX "Q_OBJECT|Q_GADGET|Q_NAMESPACE")
    if(NOT qobj)
      continue()
    endif()
    cmake_path(GET abs STEM stem)
    if(abs MATCHES "\\.cpp$")
      set(out ${outdir}/${stem}.moc) # included by the .cpp; a source only so that it is built first
    else()
      set(out ${outdir}/moc_${stem}.cpp)
    endif()
    target_sources(${target} PRIVATE ${out})
    add_custom_command(
      OUTPUT ${out}
      COMMAND Qt6::moc ${flags} -o ${out} ${abs}
      DEPENDS ${abs} Qt6::moc
      COMMAND_EXPAND_LISTS VERBATIM)
    set(any TRUE)
  endforeach()
  if(any)
    target_include_directories(${target} PRIVATE ${outdir})
  endif()
endfunction()

# ocu_add_test(NAME n SOURCES s... [LIBS l...] [XVFB] [WAITS] [TIMEOUT sec] [LABELS l...])
# A Qt Test executable registered in CTest. GUI tests run on the offscreen platform with DISPLAY unset;
# XVFB tests (OpenGL/VTK) run under xvfb-run with the xcb platform.
# The suite runs with `ctest -j8` on two cores: a test takes 4 of the 8 slots (a core) unless it is marked
# WAITS, because it spends its time waiting on the clock (timeouts, a vehicle driving, an outage), uses
# well under a quarter of a core and takes one slot, so such tests run beside the ones that compute.
function(ocu_add_test)
  cmake_parse_arguments(T "XVFB;SERIAL;WAITS" "NAME;TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  # A build that leaves a protocol out (OCU_PROTOCOLS) leaves out the tests of its libraries.
  ocu_libraries_in_build(in_build ${T_NAME} ${T_LIBS})
  if(NOT in_build)
    return()
  endif()
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE Qt6::Test ${T_LIBS})
  target_include_directories(${T_NAME} PRIVATE ${CMAKE_SOURCE_DIR}) # tests/support/, one include root
  ocu_set_warnings(${T_NAME})
  # Qt's test defines carry the absolute build and source folders; no test uses QFINDTESTDATA. Undefined, the
  # preprocessed test is the same in every clone or worktree, so ccache can share the objects between them.
  target_compile_options(${T_NAME} PRIVATE -UQT_TESTCASE_BUILDDIR -UQT_TESTCASE_SOURCEDIR)
  ocu_compile_as_test_code(${T_NAME})
  ocu_link_without_debug_info(${T_NAME})
  ocu_moc_own_sources(${T_NAME})
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
  # A console started by a test records into the build tree, never into the user's home.
  set_property(TEST ${T_NAME} APPEND PROPERTY ENVIRONMENT
               "OCU_RECORD_DIR=${CMAKE_BINARY_DIR}/test-recordings/${T_NAME}")
  if(T_WAITS)
    set_tests_properties(${T_NAME} PROPERTIES PROCESSORS 1)
  else()
    set_tests_properties(${T_NAME} PROPERTIES PROCESSORS 4)
  endif()
  if(T_SERIAL)
    set_tests_properties(${T_NAME} PROPERTIES RUN_SERIAL TRUE)
  endif()
endfunction()

# ocu_add_bench(NAME n SOURCES s... [LIBS l...]): a Google Benchmark (or harness) executable under bench/.
function(ocu_add_bench)
  cmake_parse_arguments(B "" "NAME" "SOURCES;LIBS" ${ARGN})
  # A build that leaves a protocol out (OCU_PROTOCOLS) leaves out its benchmarks too.
  ocu_libraries_in_build(in_build ${B_NAME} ${B_LIBS})
  if(NOT in_build)
    return()
  endif()
  add_executable(${B_NAME} ${B_SOURCES})
  target_link_libraries(${B_NAME} PRIVATE benchmark::benchmark ${B_LIBS})
  ocu_set_warnings(${B_NAME})
  ocu_link_without_debug_info(${B_NAME})
  ocu_moc_own_sources(${B_NAME})
endfunction()

# ocu_module_registry(TARGET t HEADER h INTERFACE cls NAMESPACE ns FUNCTION fn FACTORIES f...)
# Generates and adds to the target `std::vector<std::unique_ptr<cls>> ns::fn()`, which returns one module from each
# factory `std::unique_ptr<cls> f()`, in the order given: the protocol modules of this build, listed by CMake from
# the targets it has, so that no source file needs an #if per protocol.
function(ocu_module_registry)
  cmake_parse_arguments(R "" "TARGET;HEADER;INTERFACE;NAMESPACE;FUNCTION" "FACTORIES" ${ARGN})
  set(decls "")
  set(calls "")
  foreach(f IN LISTS R_FACTORIES)
    string(APPEND decls "std::unique_ptr<${R_INTERFACE}> ${f}();\n")
    string(APPEND calls "    out.push_back(${f}());\n")
  endforeach()
  set(out ${CMAKE_CURRENT_BINARY_DIR}/${R_FUNCTION}.cpp)
  file(CONFIGURE OUTPUT ${out} CONTENT
"// Generated by CMake (ocu_module_registry, cmake/OcuTargets.cmake): the modules of this build, in order.
#include \"${R_HEADER}\"

namespace ${R_NAMESPACE} {

${decls}
std::vector<std::unique_ptr<${R_INTERFACE}>> ${R_FUNCTION}() {
    std::vector<std::unique_ptr<${R_INTERFACE}>> out;
${calls}    return out;
}

} // namespace ${R_NAMESPACE}
" @ONLY)
  target_sources(${R_TARGET} PRIVATE ${out})
endfunction()

# ocu_targets_in(DIR OUT): every target defined in DIR and its subdirectories (for passes over all targets at
# the end of the top CMakeLists.txt: precompiled headers, unity builds).
function(ocu_targets_in dir out_var)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(s IN LISTS subdirs)
    ocu_targets_in(${s} sub)
    list(APPEND targets ${sub})
  endforeach()
  set(${out_var} ${targets} PARENT_SCOPE)
endfunction()
