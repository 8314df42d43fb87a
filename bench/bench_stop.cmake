# STOP ALL latency at the wire: the main window's action, a real click on its button (XTest, under Xvfb) and a
# headless stdin line -> first byte of each protocol's stop message on loopback (packet socket, needs root),
# idle and under a full ocu-sim load.
if(TARGET ocu_app AND TARGET ocu-sim AND TARGET ocu_jaus)
  add_executable(bench_stop ${CMAKE_CURRENT_SOURCE_DIR}/bench_stop.cpp ${CMAKE_SOURCE_DIR}/tests/support/XTestClicker.h
                            ${CMAKE_SOURCE_DIR}/tests/support/XTestClicker.cpp)
  target_link_libraries(bench_stop PRIVATE ocu_app X11::X11 X11::Xtst)
  target_compile_definitions(bench_stop PRIVATE OCU_BINARY="$<TARGET_FILE:ocu>"
                                                OCU_SIM_BINARY="$<TARGET_FILE:ocu-sim>")
  add_dependencies(bench_stop ocu ocu-sim)
  ocu_set_warnings(bench_stop)
endif()
