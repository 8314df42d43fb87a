# Precompiled headers (build time, docs/performance.md "Build and test times").
#
# Parsing the standard library and Qt headers was most of the CPU of a clean build (-ftime-report: 60-90 % of a
# TU in "phase parsing"; every test TU includes <QtTest>, i.e. all of QtCore). Three shared PCHs, each compiled
# once, are reused by every Qt target (REUSE_FROM): core (std + QtCore), gui (+ the common QtGui classes) and
# widgets (+ the common QtWidgets classes); a target gets the largest one its link closure allows, so that no TU
# sees a Qt module it does not link. The PCHs hold only third-party headers, never ours. GCC rejects a PCH whose
# flags differ, so the PCH targets get the flags every target has (-fPIC via Qt, the global options); the
# per-folder QT_TESTCASE_* defines are why <QtTest> itself is not in the PCH.
#
# Off by default in the sanitizer and fuzz builds (their own build directories, not timed); -DOCU_PCH=OFF turns it
# off anywhere. With ccache, CCACHE_SLOPPINESS=pch_defines,time_macros is needed to cache PCH users: the top
# CMakeLists.txt sets it in the compiler launcher and scripts/build.sh exports it.
if(OCU_SANITIZE OR OCU_FUZZ)
  set(_ocu_pch_default OFF)
else()
  set(_ocu_pch_default ON)
endif()
option(OCU_PCH "Precompiled headers shared by the Qt targets (faster clean builds)" ${_ocu_pch_default})

set(OCU_PCH_STD
    <algorithm> <array> <atomic> <chrono> <cmath> <cstdint> <cstring> <deque> <functional> <map> <memory> <mutex>
    <optional> <set> <string> <string_view> <thread> <unordered_map> <utility> <variant> <vector>)
set(OCU_PCH_CORE <QtCore/QtCore>)
# No QOpenGL* here: GL headers must come after GLEW in the VTK code (widgets/view3d).
set(OCU_PCH_GUI
    <QtGui/QColor> <QtGui/QFont> <QtGui/QFontMetrics> <QtGui/QIcon> <QtGui/QImage> <QtGui/QKeyEvent>
    <QtGui/QMouseEvent> <QtGui/QPainter> <QtGui/QPainterPath> <QtGui/QPen> <QtGui/QPixmap> <QtGui/QPolygonF>
    <QtGui/QStandardItemModel> <QtGui/QTransform> <QtGui/QGuiApplication> <QtGui/QAction>)
set(OCU_PCH_WIDGETS
    <QtWidgets/QAbstractItemView> <QtWidgets/QApplication> <QtWidgets/QCheckBox> <QtWidgets/QComboBox>
    <QtWidgets/QDialog> <QtWidgets/QFormLayout> <QtWidgets/QGridLayout> <QtWidgets/QGroupBox>
    <QtWidgets/QHBoxLayout> <QtWidgets/QHeaderView> <QtWidgets/QLabel> <QtWidgets/QLineEdit> <QtWidgets/QMenu>
    <QtWidgets/QMessageBox> <QtWidgets/QPlainTextEdit> <QtWidgets/QPushButton> <QtWidgets/QScrollArea>
    <QtWidgets/QSpinBox> <QtWidgets/QSplitter> <QtWidgets/QStyledItemDelegate> <QtWidgets/QTableView>
    <QtWidgets/QTabWidget> <QtWidgets/QToolBar> <QtWidgets/QToolButton> <QtWidgets/QTreeView>
    <QtWidgets/QVBoxLayout> <QtWidgets/QWidget>)

# Collects into out_var which of Qt6::Core / Qt6::Gui / Qt6::Widgets reach target's compile through its usage
# requirements (its own link libraries, then their INTERFACE_LINK_LIBRARIES without $<LINK_ONLY:>), and Pthread
# when -pthread may (pkg-config targets, e.g. GStreamer's, add it; they are not visible from here).
function(_ocu_pch_qt_closure target out_var)
  set(seen "")
  set(found "")
  get_target_property(todo ${target} LINK_LIBRARIES)
  if(NOT todo)
    set(todo "")
  endif()
  while(todo)
    list(POP_FRONT todo t)
    if(t MATCHES "^PkgConfig::")
      list(APPEND found Pthread)
    endif()
    if(t IN_LIST seen OR NOT TARGET ${t})
      continue()
    endif()
    list(APPEND seen ${t})
    get_target_property(aliased ${t} ALIASED_TARGET)
    if(aliased)
      set(t ${aliased})
    endif()
    foreach(m Core Gui Widgets)
      if(t STREQUAL "Qt6::${m}")
        list(APPEND found ${m})
      endif()
    endforeach()
    get_target_property(opts ${t} INTERFACE_COMPILE_OPTIONS)
    if(opts AND "-pthread" IN_LIST opts)
      list(APPEND found Pthread)
    endif()
    get_target_property(libs ${t} INTERFACE_LINK_LIBRARIES)
    if(libs)
      foreach(l IN LISTS libs)
        if(NOT l MATCHES "^\\$<")
          list(APPEND todo ${l})
        endif()
      endforeach()
    endif()
  endwhile()
  set(${out_var} ${found} PARENT_SCOPE)
endfunction()


# Loading a PCH costs ~0.7 s CPU even for an empty TU. AUTOMOC's mocs_compilation.cpp is empty when no header of
# the target (listed, or beside a listed .cpp, as AUTOMOC looks) declares Q_OBJECT & co (tests include their own
# .moc): such a file gets no PCH. A wrong guess only costs time, never correctness.
function(_ocu_pch_skip_empty_moc t)
  get_target_property(automoc ${t} AUTOMOC)
  if(NOT automoc)
    return()
  endif()
  get_target_property(srcs ${t} SOURCES)
  get_target_property(sdir ${t} SOURCE_DIR)
  get_target_property(bdir ${t} BINARY_DIR)
  foreach(src IN LISTS srcs)
    cmake_path(ABSOLUTE_PATH src BASE_DIRECTORY ${sdir} OUTPUT_VARIABLE abs)
    cmake_path(REMOVE_EXTENSION abs LAST_ONLY OUTPUT_VARIABLE stem)
    foreach(h ${stem}.h ${stem}.hpp ${stem}_p.h)
      if(EXISTS ${h})
        file(STRINGS ${h} qobj REGEX "Q_OBJECT|Q_GADGET|Q_NAMESPACE")
        if(qobj)
          return()
        endif()
      endif()
    endforeach()
  endforeach()
  set_source_files_properties(${bdir}/${t}_autogen/mocs_compilation.cpp TARGET_DIRECTORY ${t}
                              PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
endfunction()

# Call once at the end of the top CMakeLists.txt, when every target exists.
function(ocu_apply_pch)
  if(NOT OCU_PCH)
    return()
  endif()
  set(empty ${CMAKE_BINARY_DIR}/ocu_pch_empty.cpp)
  file(CONFIGURE OUTPUT ${empty} CONTENT "// Generated: the precompiled headers' carrier (cmake/OcuPch.cmake).\n")
  set(hdrs_Core ${OCU_PCH_STD} ${OCU_PCH_CORE})
  set(hdrs_Gui ${hdrs_Core} ${OCU_PCH_GUI})
  set(hdrs_Widgets ${hdrs_Gui} ${OCU_PCH_WIDGETS})
  foreach(m Core Gui Widgets)
    string(TOLOWER ${m} lm)
    add_library(ocu_pch_${lm} OBJECT ${empty})
    # Qt wants -fPIC, so every Qt target has it.
    set_target_properties(ocu_pch_${lm} PROPERTIES AUTOMOC OFF AUTORCC OFF AUTOUIC OFF EXCLUDE_FROM_ALL ON
                                                   POSITION_INDEPENDENT_CODE ON)
    target_link_libraries(ocu_pch_${lm} PRIVATE Qt6::${m})
    target_precompile_headers(ocu_pch_${lm} PRIVATE ${hdrs_${m}})
  endforeach()

  ocu_targets_in(${CMAKE_SOURCE_DIR} targets)
  set(n 0)
  foreach(t IN LISTS targets)
    get_target_property(type ${t} TYPE)
    if(NOT type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$" OR t MATCHES "^ocu_pch_")
      continue()
    endif()
    get_target_property(no_pch ${t} OCU_NO_PCH)
    if(no_pch)
      continue()
    endif()
    _ocu_pch_qt_closure(${t} qt)
    if("Pthread" IN_LIST qt) # a PCH built without _REENTRANT is not valid for its TUs
      continue()
    elseif("Widgets" IN_LIST qt)
      set(v widgets)
    elseif("Gui" IN_LIST qt)
      set(v gui)
    elseif("Core" IN_LIST qt)
      set(v core)
    else()
      # No PCH for the non-Qt targets (protocols/, sim/): loading a 200 MB std+Asio+JSON PCH cost more than it
      # saved (protocols/common, protocols/jaus: 9 TUs 19.2 s CPU without, 20.8 s with).
      continue()
    endif()
    target_precompile_headers(${t} REUSE_FROM ocu_pch_${v})
    _ocu_pch_skip_empty_moc(${t})
    # A PCH GCC cannot use (flags differ) silently costs the parse again: say so, without failing the build.
    target_compile_options(${t} PRIVATE -Winvalid-pch -Wno-error=invalid-pch)
    math(EXPR n "${n} + 1")
  endforeach()
  message(STATUS "Precompiled headers: ${n} Qt targets reuse ocu_pch_{core,gui,widgets} (OCU_PCH)")
endfunction()
