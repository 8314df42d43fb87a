# Fleet models: 1,000 machines at 10 Hz through a bridge's coalescer into FleetModel (+ sorted proxy).
if(TARGET ocu_models_testing)
  ocu_add_bench(NAME bench_models SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench_models.cpp LIBS ocu_models_testing)
endif()
