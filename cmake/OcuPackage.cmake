# The Debian package `ocu` (scripts/package.sh: a Release build with -DOCU_PACKAGE=ON, then CPack's DEB
# generator). Adds to the install() rules of cmake/OcuInstall.cmake what only a package needs: the menu entry, the
# service unit, man pages made from --help, the example site file, the copyright and changelog files; and the
# maintainer scripts that create the service's user and folders (docs/packaging.md).
include(GNUInstallDirs)

# Man pages from the binaries' own --help and --version (help2man), so they never disagree with them.
find_program(OCU_HELP2MAN help2man REQUIRED)
set(_man_dir ${CMAKE_BINARY_DIR}/packaging/man)
set(_man_pages)
foreach(exe ocu ocu-sim)
  if(exe STREQUAL "ocu")
    set(_what "mixed-fleet operator control unit (console and headless monitor)")
  else()
    set(_what "the OCU's simulated site (JAUS, ISO 23725 and OSYRIS machines) on its own")
  endif()
  add_custom_command(
    OUTPUT ${_man_dir}/${exe}.1.gz
    COMMAND ${CMAKE_COMMAND} -E make_directory ${_man_dir}
    COMMAND ${CMAKE_COMMAND} -E env LANG=C LC_ALL=C QT_QPA_PLATFORM=offscreen
            ${OCU_HELP2MAN} --no-info --section=1 --name=${_what}
            --output=${_man_dir}/${exe}.1 $<TARGET_FILE:${exe}>
    COMMAND gzip -9nf ${_man_dir}/${exe}.1
    DEPENDS ${exe} VERBATIM
    COMMENT "Man page of ${exe} from its --help")
  list(APPEND _man_pages ${_man_dir}/${exe}.1.gz)
endforeach()
add_custom_target(ocu_man_pages ALL DEPENDS ${_man_pages})
install(FILES ${_man_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT console)

# The maintainer address (a reserved .invalid domain until the project names a real one).
set(OCU_PACKAGE_MAINTAINER "Operator Control Unit developers <maintainers@ocu.invalid>"
    CACHE STRING "Maintainer of the Debian package (name <address>)")
# A Debian changelog (Policy §12.7), one entry for this version.
string(TIMESTAMP _date "%a, %d %b %Y %H:%M:%S +0000" UTC)
file(WRITE ${CMAKE_BINARY_DIR}/packaging/changelog
     "ocu (${OCU_VERSION_STRING}) unstable; urgency=medium\n\n"
     "  * Built from the repository at ${OCU_VERSION_STRING}.\n\n"
     " -- ${OCU_PACKAGE_MAINTAINER}  ${_date}\n")
execute_process(COMMAND gzip -9nf ${CMAKE_BINARY_DIR}/packaging/changelog)
install(FILES ${CMAKE_BINARY_DIR}/packaging/changelog.gz ${CMAKE_SOURCE_DIR}/packaging/debian/copyright
        DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT console)

install(FILES ${CMAKE_SOURCE_DIR}/packaging/ocu.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications
        COMPONENT console)
install(FILES ${CMAKE_SOURCE_DIR}/packaging/ocu-monitor@.service DESTINATION lib/systemd/system
        COMPONENT console)
# The example for /etc/ocu/<site>.json: the built-in simulated site (it runs anywhere, docs/packaging.md).
install(FILES ${CMAKE_SOURCE_DIR}/resources/sites/simulated-site.json DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples
        RENAME demo-site.json COMPONENT console)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME ocu)
set(CPACK_PACKAGE_VERSION ${OCU_VERSION_STRING})
set(CPACK_PACKAGE_CONTACT ${OCU_PACKAGE_MAINTAINER})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "mixed-fleet operator control unit")
# The extended description (the synopsis is CPACK_PACKAGE_DESCRIPTION_SUMMARY); one string: a CMake list would
# put semicolons into it.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "One console for JAUS unmanned ground vehicles, ISO 23725 autonomous haulage\n\
and OSYRIS rollers and pavers: site map, 3D view, fleet list, alarms,\n\
dispatch, compaction coverage, flight recorder and replay. Also a headless\n\
monitor run as the systemd service ocu-monitor@SITE, commanded through a\n\
local socket, and ocu-sim, a simulated site.")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# The runtime libraries from the binaries themselves (dpkg-shlibdeps), never a -dev package; adduser for postinst.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "adduser, libqt6positioning6-plugins") # and own position plugins (loaded, not linked)
# The teleop video (rtspsrc, h264parse, avdec_h264) and ocu-sim's cameras (x264enc) are GStreamer plugins: without
# them the console runs and shows no video.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "gstreamer1.0-plugins-good, gstreamer1.0-plugins-bad, gstreamer1.0-libav, \
gstreamer1.0-plugins-ugly")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${CMAKE_SOURCE_DIR}/packaging/debian/postinst
    ${CMAKE_SOURCE_DIR}/packaging/debian/prerm ${CMAKE_SOURCE_DIR}/packaging/debian/postrm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR}/packages)
include(CPack)
