# What `cmake --install` puts where (GNU layout under CMAKE_INSTALL_PREFIX): the console and the simulated site,
# their translations, the resources a site file may name (demo sites, designs, symbols), the icon and the
# documentation. The translations and the built-in site are also embedded in the binary; the installed copies are
# for people and for tools (a package's file list, a site file that names a design).
include(GNUInstallDirs)

foreach(exe ocu ocu-sim)
  if(TARGET ${exe})
    install(TARGETS ${exe} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT console)
  endif()
endforeach()

# lrelease writes the .qm files beside the app target's build folder (app/CMakeLists.txt).
foreach(lang de fr)
  install(FILES ${CMAKE_BINARY_DIR}/app/ocu_${lang}.qm DESTINATION ${CMAKE_INSTALL_DATADIR}/ocu/translations
          COMPONENT console OPTIONAL)
endforeach()

install(DIRECTORY ${CMAKE_SOURCE_DIR}/resources/sites ${CMAKE_SOURCE_DIR}/resources/designs
                  ${CMAKE_SOURCE_DIR}/resources/symbols
        DESTINATION ${CMAKE_INSTALL_DATADIR}/ocu COMPONENT console)
install(FILES ${CMAKE_SOURCE_DIR}/resources/icons/ocu.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps COMPONENT console)

install(FILES ${CMAKE_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT console)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT console
        FILES_MATCHING PATTERN "*.md" PATTERN "*.png")

if(OCU_BUILD_TESTS)
  add_test(NAME install_rules COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${CMAKE_BINARY_DIR}
                                      -DPREFIX=${CMAKE_BINARY_DIR}/test-install -P ${CMAKE_SOURCE_DIR}/cmake/CheckInstall.cmake)
  set_tests_properties(install_rules PROPERTIES LABELS rules TIMEOUT 60)
endif()
