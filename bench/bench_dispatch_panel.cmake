# Dispatch panel: GUI-thread cost of a 1,000-truck dispatch update (model + queues + repaint).
if(TARGET ocu_dispatch_widgets AND TARGET ocu_models_testing)
  ocu_add_bench(NAME bench_dispatch_panel SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bench_dispatch_panel.cpp
                LIBS ocu_dispatch_widgets ocu_models_testing)
endif()
