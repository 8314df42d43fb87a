# Run by the CTest test install_rules: installs the build into a throwaway prefix and checks that each part a
# package needs is there. -DBUILD_DIR=... -DPREFIX=...
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX} RESULT_VARIABLE rc
                OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc}): ${err}")
endif()
foreach(f bin/ocu bin/ocu-sim share/ocu/translations/ocu_de.qm share/ocu/translations/ocu_fr.qm
          share/ocu/sites/simulated-site.json share/ocu/sites/paving-demo.json share/ocu/designs/paving-job.xml
          share/ocu/symbols/roller.svg share/icons/hicolor/scalable/apps/ocu.svg share/doc/ocu/README.md
          share/doc/ocu/architecture.md)
  if(NOT EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
file(REMOVE_RECURSE ${PREFIX})
message(STATUS "install rules: every expected file installed")
