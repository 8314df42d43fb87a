# 2D site map: full repaint at 1920x1080 offscreen with 1,000 machines, 5,000 ways and a 1 km² pass-count layer.
if(TARGET ocu_widgets)
  ocu_add_bench(NAME bench_sitemap SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench_sitemap.cpp LIBS ocu_widgets)
endif()
