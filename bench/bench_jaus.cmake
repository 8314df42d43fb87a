ocu_add_bench(NAME bench_jaus SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench_jaus.cpp LIBS ocu_sim_jaus)
