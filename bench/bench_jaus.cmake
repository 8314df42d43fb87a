ocu_add_bench(NAME bench_jaus SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench_jaus.cpp LIBS ocu_sim_jaus)
# The simulated cameras' rendering cost per frame.
ocu_add_bench(NAME bench_sim_camera SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench_sim_camera.cpp LIBS ocu_sim_jaus)
# The mission plan editor: frame time while dragging a waypoint of a 1,000-point route at 1920x1080.
ocu_add_bench(NAME bench_mission_editor SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench_mission_editor.cpp
  LIBS ocu_jaus_widgets)
# Mission upload + read-back of a 1,000-waypoint list on loopback (time, datagrams).
ocu_add_bench(NAME bench_mission SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench_mission.cpp LIBS ocu_sim_jaus)
