# cmake/docs.cmake - the API reference, built with Doxygen.
#
# include(cmake/docs.cmake) from the top-level CMakeLists.txt, after project().
#
#   target xfgcu_docs   defined whenever Doxygen is found; builds the HTML
#                       reference of include/xfgcu/*.h into
#                       ${PROJECT_BINARY_DIR}/docs/api/html. Fails on any
#                       Doxygen warning (an undocumented entity included).
#   XFGCU_BUILD_DOCS    ON by default in a top-level build when Doxygen is
#                       found, OFF otherwise (and under add_subdirectory).
#                       ON: build it with ALL, install the HTML to
#                       ${CMAKE_INSTALL_DOCDIR}/api, and fail at configure
#                       time if Doxygen is missing. OFF: build it only on
#                       request (cmake --build <dir> --target xfgcu_docs).
include_guard(GLOBAL)

include(GNUInstallDirs) # CMAKE_INSTALL_DOCDIR

# On by default in a top-level build when Doxygen is there, so that the
# installed package carries the reference; a consumer's add_subdirectory never
# builds it unless asked.
find_package(Doxygen QUIET)
if(DOXYGEN_FOUND AND XFGCU_TOP_LEVEL)
  set(_xf_docs_default ON)
else()
  set(_xf_docs_default OFF)
endif()
option(XFGCU_BUILD_DOCS "Build the API reference with Doxygen as part of ALL, and install it" ${_xf_docs_default})
if(XFGCU_TOP_LEVEL AND NOT DOXYGEN_FOUND AND NOT XFGCU_BUILD_DOCS)
  message(STATUS "xfgcu: API reference off: doxygen not found (apt-get install doxygen)")
endif()

if(NOT DOXYGEN_FOUND)
  if(XFGCU_BUILD_DOCS)
    message(FATAL_ERROR "XFGCU_BUILD_DOCS is ON but Doxygen was not found (install doxygen, or set XFGCU_BUILD_DOCS=OFF)")
  endif()
  return()
endif()

set(XFGCU_DOCS_OUTPUT_DIR ${PROJECT_BINARY_DIR}/docs/api)
set(_xf_doxyfile ${PROJECT_BINARY_DIR}/docs/Doxyfile)
configure_file(${PROJECT_SOURCE_DIR}/docs/Doxyfile.in ${_xf_doxyfile} @ONLY)

file(GLOB_RECURSE _xf_doc_headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/include/xfgcu/*.h)
# Touched only when Doxygen succeeds, so a run that failed on a warning is run again.
set(_xf_doc_stamp ${XFGCU_DOCS_OUTPUT_DIR}/xfgcu_docs.stamp)

# Old pages of renamed or removed entities would linger: start from empty.
add_custom_command(
  OUTPUT ${_xf_doc_stamp}
  COMMAND ${CMAKE_COMMAND} -E remove_directory ${XFGCU_DOCS_OUTPUT_DIR}/html
  COMMAND ${CMAKE_COMMAND} -E make_directory ${XFGCU_DOCS_OUTPUT_DIR}
  COMMAND Doxygen::doxygen ${_xf_doxyfile}
  COMMAND ${CMAKE_COMMAND} -E touch ${_xf_doc_stamp}
  DEPENDS ${_xf_doxyfile} ${_xf_doc_headers} ${PROJECT_SOURCE_DIR}/docs/api-mainpage.md
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
  COMMENT "Building the API reference (Doxygen) in ${XFGCU_DOCS_OUTPUT_DIR}/html"
  VERBATIM)

if(XFGCU_BUILD_DOCS)
  add_custom_target(xfgcu_docs ALL DEPENDS ${_xf_doc_stamp})
  install(DIRECTORY ${XFGCU_DOCS_OUTPUT_DIR}/html/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/api)
else()
  add_custom_target(xfgcu_docs DEPENDS ${_xf_doc_stamp})
endif()

unset(_xf_doxyfile)
unset(_xf_doc_headers)
unset(_xf_doc_stamp)
