# The coverage report of a 10 km x 12 m job, 0.34 m cells, 3 lifts (~3 M cells).
if(TARGET ocu_coverage)
  ocu_add_bench(NAME bench_coverage_report SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench_coverage_report.cpp
                LIBS ocu_coverage)
  target_compile_definitions(bench_coverage_report PRIVATE OCU_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
endif()
