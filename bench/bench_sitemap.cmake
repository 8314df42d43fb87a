# 2D site map: full repaint at 1920x1080 offscreen with 1,000 machines, 5,000 ways and a 1 km² pass-count layer;
# with the ISO 23725 simulator also the simulated pit with its hillshade background.
if(TARGET ocu_widgets)
  set(_sitemap_libs ocu_widgets)
  if(TARGET ocu_sim_iso23725)
    list(APPEND _sitemap_libs ocu_sim_iso23725)
  endif()
  ocu_add_bench(NAME bench_sitemap SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench_sitemap.cpp LIBS ${_sitemap_libs})
  if(TARGET bench_sitemap AND TARGET ocu_sim_iso23725)
    target_compile_definitions(bench_sitemap PRIVATE OCU_BENCH_HAVE_PIT)
  endif()
endif()
