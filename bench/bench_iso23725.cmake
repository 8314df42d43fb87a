# ISO 23725 benchmarks: codec rate, large map parse time, 1,000 simulated trucks at 10 Hz over loopback.
if(TARGET ocu_sim_iso23725)
  ocu_add_bench(NAME bench_iso23725 SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_iso23725.cpp LIBS ocu_sim_iso23725)
  set_target_properties(bench_iso23725 PROPERTIES AUTOMOC OFF)
endif()
# The positions path on the console's side: 1,000 trucks at 10 Hz through IsoStack and IsoBridge into the
# FleetModel (CPU per position on the io and GUI threads, coalescer pushes, delivery latency).
if(TARGET ocu_sim_iso23725 AND TARGET ocu_bridges)
  ocu_add_bench(NAME bench_iso_bridge SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_iso_bridge.cpp
                LIBS ocu_sim_iso23725 ocu_bridges)
endif()
# Assignment request -> response round trip (p50/p99) with 1,000 trucks at 10 Hz on the same link.
if(TARGET ocu_sim_iso23725 AND TARGET ocu_bridges)
  ocu_add_bench(NAME bench_iso_assign SOURCES ${CMAKE_CURRENT_LIST_DIR}/bench_iso_assign.cpp
                LIBS ocu_sim_iso23725 ocu_bridges)
endif()
