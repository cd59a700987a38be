# Finds every dependency; a missing one stops configuration with the Debian package to
# install. scripts/install-deps.sh installs all of them.

find_package(PkgConfig REQUIRED)

macro(plumbago_require name package)
  find_package(${name} CONFIG QUIET ${ARGN})
  if(NOT ${name}_FOUND)
    message(FATAL_ERROR "Plumbago needs ${name}: install the Debian package '${package}' "
                        "(or run scripts/install-deps.sh).")
  endif()
endmacro()

plumbago_require(glm libglm-dev)
plumbago_require(nlohmann_json nlohmann-json3-dev)
plumbago_require(pugixml libpugixml-dev)
plumbago_require(TBB libtbb-dev)
# OpenImageIO through pkg-config: Debian's CMake config of it names /usr/include/opencv4,
# which exists only when OpenCV's headers happen to be installed.
pkg_check_modules(OpenImageIO IMPORTED_TARGET OpenImageIO)
if(NOT OpenImageIO_FOUND)
  message(FATAL_ERROR "Plumbago needs OpenImageIO: install the Debian package 'libopenimageio-dev'.")
endif()
plumbago_require(OpenMesh libopenmesh-dev)
plumbago_require(Eigen3 libeigen3-dev)
plumbago_require(embree libembree-dev)
plumbago_require(CLI11 libcli11-dev)
plumbago_require(GTest "libgtest-dev libgmock-dev")
plumbago_require(benchmark libbenchmark-dev)

set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
set(CGAL_DATA_DIR "${CMAKE_BINARY_DIR}")
find_package(CGAL QUIET)
if(NOT CGAL_FOUND)
  message(FATAL_ERROR "Plumbago needs CGAL: install the Debian package 'libcgal-dev'.")
endif()

if(PLUMBAGO_GL STREQUAL "egl")
  set(OpenGL_GL_PREFERENCE GLVND)
  find_package(OpenGL QUIET COMPONENTS OpenGL EGL)
  if(NOT TARGET OpenGL::OpenGL OR NOT TARGET OpenGL::EGL)
    message(FATAL_ERROR "Plumbago's EGL build needs libOpenGL and libEGL: install the "
                        "Debian packages 'libopengl-dev libegl-dev libgl-dev'.")
  endif()
else()
  pkg_check_modules(OSMesa IMPORTED_TARGET osmesa)
  if(NOT OSMesa_FOUND)
    message(FATAL_ERROR "Plumbago's OSMesa build needs OSMesa: install the Debian package "
                        "'libosmesa6-dev'.")
  endif()
endif()

# Optional: the viewer (`plumbago view`) needs GLFW and Dear ImGui (Debian 1.86: its
# libimgui.a holds the GLFW and OpenGL 3 backends) and the EGL build (the OSMesa build's
# GL entry points would shadow the window's). Without them everything else builds.
pkg_check_modules(GLFW IMPORTED_TARGET glfw3)
pkg_check_modules(IMGUI IMPORTED_TARGET imgui)  # and stb, which its font atlas calls
if(NOT PLUMBAGO_GL STREQUAL "egl")
  set(PLUMBAGO_VIEWER OFF)
  message(STATUS "Plumbago: not building the viewer (plumbago view): it needs the EGL build")
elseif(GLFW_FOUND AND IMGUI_FOUND)
  set(PLUMBAGO_VIEWER ON)
  message(STATUS "Plumbago: building the viewer (plumbago view) with GLFW ${GLFW_VERSION} and Dear ImGui ${IMGUI_VERSION}")
else()
  set(PLUMBAGO_VIEWER OFF)
  message(STATUS "Plumbago: not building the viewer (plumbago view): GLFW or Dear ImGui not found; "
                 "install the Debian packages 'libglfw3-dev libimgui-dev' (or run scripts/install-deps.sh)")
endif()

# Optional: the Python module (python/) needs pybind11 and Python's headers; without them
# everything else builds. Debian's python3 (numpy, pytest, matplotlib: scripts/install-deps.sh)
# unless Python_EXECUTABLE names another; PATH may name another first (pyenv). Not in the
# sanitizer build, whose objects python3 could not load.
if(PLUMBAGO_SANITIZE)
  set(PLUMBAGO_PYTHON OFF)
elseif(PLUMBAGO_PYTHON)
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(Python 3 QUIET COMPONENTS Interpreter Development.Module)
  find_package(pybind11 CONFIG QUIET)
  if(Python_FOUND AND pybind11_FOUND)
    message(STATUS "Plumbago: building the Python module with pybind11 ${pybind11_VERSION} for ${Python_EXECUTABLE}")
  else()
    set(PLUMBAGO_PYTHON OFF)
    message(STATUS "Plumbago: not building the Python module: pybind11 or Python's headers not found; install "
                   "the Debian packages 'pybind11-dev python3-dev' (or run scripts/install-deps.sh)")
  endif()
endif()
