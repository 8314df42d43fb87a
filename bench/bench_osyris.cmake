# OSYRIS: codec decode rate and pass-count ingest rate.
ocu_add_bench(NAME bench_osyris SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/osyris/bench_osyris.cpp LIBS ocu_osyris)
