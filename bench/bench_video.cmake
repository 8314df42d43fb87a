# Glass-to-glass video latency on loopback (capture time code -> rendered widget), decode CPU.
if(TARGET ocu_video_widgets AND TARGET ocu_test_rtsp AND TARGET ocu_sim_jaus)
  add_executable(bench_video ${CMAKE_CURRENT_SOURCE_DIR}/bench_video.cpp)
  target_link_libraries(bench_video PRIVATE ocu_video_widgets ocu_test_rtsp ocu_sim_jaus)
  ocu_set_warnings(bench_video)
endif()
