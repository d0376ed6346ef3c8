# The assembly viewer's page (assembly.html's template) as a C++ source for papercraft_export:
# `npm ci` installs the pinned packages of viewer/package-lock.json into <build>/viewer (once
# per lock file), then viewer/build.mjs bundles viewer/src with three.js (esbuild) into the
# page and writes it as <build>/viewer/assembly_template.cpp. Included by nodes/CMakeLists.txt,
# so the generated source belongs to that directory's papercraft_export.
find_program(PAPERCRAFT_NODE node)
find_program(PAPERCRAFT_NPM npm)
if(NOT PAPERCRAFT_NODE OR NOT PAPERCRAFT_NPM)
  message(FATAL_ERROR "node and npm are needed to build the assembly viewer: run "
                      "scripts/install-deps.sh (Debian packages nodejs and npm)")
endif()
set(PAPERCRAFT_VIEWER_DIR ${PROJECT_BINARY_DIR}/viewer)
set(PAPERCRAFT_VIEWER_MODULES ${PAPERCRAFT_VIEWER_DIR}/node_modules)
set(viewer_source ${PROJECT_SOURCE_DIR}/viewer)
set(viewer_installed ${PAPERCRAFT_VIEWER_DIR}/npm-ci.stamp)
add_custom_command(
  OUTPUT ${viewer_installed}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${PAPERCRAFT_VIEWER_DIR}
  COMMAND ${CMAKE_COMMAND} -E copy ${viewer_source}/package.json ${viewer_source}/package-lock.json
          ${PAPERCRAFT_VIEWER_DIR}
  COMMAND ${PAPERCRAFT_NPM} ci --no-audit --no-fund --loglevel=error
  COMMAND ${CMAKE_COMMAND} -E touch ${viewer_installed}
  WORKING_DIRECTORY ${PAPERCRAFT_VIEWER_DIR}
  DEPENDS ${viewer_source}/package.json ${viewer_source}/package-lock.json
  COMMENT "Installing the assembly viewer's npm packages (npm ci)"
  VERBATIM)
file(GLOB viewer_sources CONFIGURE_DEPENDS ${viewer_source}/src/*)
set(PAPERCRAFT_VIEWER_TEMPLATE ${PAPERCRAFT_VIEWER_DIR}/assembly_template.cpp)
add_custom_command(
  OUTPUT ${PAPERCRAFT_VIEWER_TEMPLATE} ${PAPERCRAFT_VIEWER_DIR}/assembly_template.html
  COMMAND ${PAPERCRAFT_NODE} ${viewer_source}/build.mjs --modules ${PAPERCRAFT_VIEWER_MODULES}
          --html ${PAPERCRAFT_VIEWER_DIR}/assembly_template.html
          --cpp ${PAPERCRAFT_VIEWER_TEMPLATE}
  DEPENDS ${viewer_installed} ${viewer_source}/build.mjs ${viewer_sources}
  COMMENT "Bundling the assembly viewer (three.js, esbuild)"
  VERBATIM)
