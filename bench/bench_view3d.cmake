# 3D view: 1,000 machines updated through the fast path and rendered headless (EGL surfaceless, llvmpipe).
if(TARGET ocu_view3d)
  ocu_add_bench(NAME bench_view3d SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench_view3d.cpp LIBS ocu_view3d)
endif()
