# Teleop latency: axis event -> SetWrenchEffort at the simulated UGV under a 1,000-machine model load.
if(TARGET ocu_jaus_widgets AND TARGET ocu_bridges AND TARGET ocu_models_testing AND TARGET ocu_sim_jaus)
  add_executable(bench_teleop ${CMAKE_CURRENT_SOURCE_DIR}/bench_teleop.cpp)
  target_link_libraries(bench_teleop PRIVATE ocu_jaus_widgets ocu_bridges ocu_models_testing ocu_sim_jaus)
  ocu_set_warnings(bench_teleop)
endif()
