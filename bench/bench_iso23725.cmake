# ISO 23725 benchmarks: codec rate, large map parse time, 1,000 simulated trucks at 10 Hz over loopback.
if(TARGET ocu_sim_iso23725)
  ocu_add_bench(NAME bench_iso23725 SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_iso23725.cpp LIBS ocu_sim_iso23725)
  set_target_properties(bench_iso23725 PROPERTIES AUTOMOC OFF)
endif()
