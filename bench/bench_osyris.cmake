# OSYRIS: codec decode rate and pass-count ingest rate.
ocu_add_bench(NAME bench_osyris SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/osyris/bench_osyris.cpp LIBS ocu_osyris)
# A 10 km x 12 m job, 3 lifts: memory, snapshot, overlay redraw at zoom levels, restart.
ocu_add_bench(NAME bench_passcount_scale SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/osyris/bench_passcount_scale.cpp
              LIBS ocu_widgets ocu_bridges ocu_osyris)
