# Flight recorder cost (1,000 machines x 10 Hz), MB per hour, seek time, replay at 16x.
if(TARGET ocu_recording)
  ocu_add_bench(NAME bench_recording SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench_recording.cpp LIBS ocu_recording)
endif()
