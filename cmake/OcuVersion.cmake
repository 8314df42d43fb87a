# The version `ocu --version`, Help > About and the Debian package show: from the repository at configure time.
#   a tag vX.Y.Z on the commit        -> X.Y.Z
#   N commits after the tag vX.Y.Z    -> X.Y.Z+N.gHASH
#   no such tag                       -> PROJECT_VERSION+gitN.gHASH (N = commits in the history)
# Digits first and '+' for the rest, so dpkg orders later builds after earlier ones (Debian Policy §5.6.12).
# Outside a git checkout (a source archive): PROJECT_VERSION. Sets OCU_VERSION_STRING.
set(OCU_VERSION_STRING ${PROJECT_VERSION})
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --tags --long --match "v[0-9]*"
                  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR} OUTPUT_VARIABLE _describe RESULT_VARIABLE _rc
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(_rc EQUAL 0 AND _describe MATCHES "^v([0-9][^-]*)-([0-9]+)-g([0-9a-f]+)$")
    if(CMAKE_MATCH_2 EQUAL 0)
      set(OCU_VERSION_STRING ${CMAKE_MATCH_1})
    else()
      set(OCU_VERSION_STRING ${CMAKE_MATCH_1}+${CMAKE_MATCH_2}.g${CMAKE_MATCH_3})
    endif()
  else()
    execute_process(COMMAND ${GIT_EXECUTABLE} rev-list --count HEAD WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
                    OUTPUT_VARIABLE _count RESULT_VARIABLE _rc1 OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --short HEAD WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
                    OUTPUT_VARIABLE _hash RESULT_VARIABLE _rc2 OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(_rc1 EQUAL 0 AND _rc2 EQUAL 0)
      set(OCU_VERSION_STRING ${PROJECT_VERSION}+git${_count}.g${_hash})
    endif()
  endif()
endif()
message(STATUS "OCU version: ${OCU_VERSION_STRING}")
