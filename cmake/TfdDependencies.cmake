# Finds the Debian bookworm packages tfd builds on (see docs/building.md).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(TBB REQUIRED CONFIG)
find_package(OpenEXR REQUIRED CONFIG)
find_package(Imath REQUIRED CONFIG)
find_package(nlohmann_json REQUIRED CONFIG)
find_package(CLI11 REQUIRED CONFIG)
find_package(muparser REQUIRED CONFIG)
find_package(Threads REQUIRED)

# TetGen: TETLIBRARY makes failures throw an int instead of calling exit().
find_path(TETGEN_INCLUDE_DIR tetgen.h REQUIRED)
find_library(TETGEN_LIBRARY tet REQUIRED)
add_library(tfd::tetgen INTERFACE IMPORTED)
target_include_directories(tfd::tetgen INTERFACE ${TETGEN_INCLUDE_DIR})
target_link_libraries(tfd::tetgen INTERFACE ${TETGEN_LIBRARY})
target_compile_definitions(tfd::tetgen INTERFACE TETLIBRARY)

# OpenVDB 10 ships only a find module, in its own folder; add it after TBB and OpenEXR are
# found, since that folder also holds older find modules for them.
find_path(OPENVDB_MODULE_DIR FindOpenVDB.cmake
          PATHS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenVDB
                /usr/lib/cmake/OpenVDB /usr/local/lib/cmake/OpenVDB REQUIRED)
list(APPEND CMAKE_MODULE_PATH ${OPENVDB_MODULE_DIR})
find_package(OpenVDB REQUIRED)

# OpenGL through GLVND (libOpenGL, no GLX) and EGL: render/ draws into whatever context is
# current (the editor's QOpenGLWidget under X, or a surfaceless EGL context for `tfd render`).
find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)
find_package(PNG REQUIRED)
if(TFD_BUILD_EDITOR)
  find_package(Qt6 6.2 REQUIRED COMPONENTS Widgets OpenGL OpenGLWidgets)
endif()

if(TFD_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(TFD_BUILD_BENCH)
  find_package(benchmark REQUIRED)
  # CHOLMOD (SuiteSparse) is only the direct-solver baseline of bench/propagate_bench.cpp; no
  # library links it. Optional: without it that one benchmark is left out. No CMake package on
  # bookworm.
  find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  find_library(CHOLMOD_LIBRARY cholmod)
  if(CHOLMOD_INCLUDE_DIR AND CHOLMOD_LIBRARY)
    add_library(tfd::cholmod INTERFACE IMPORTED)
    target_include_directories(tfd::cholmod INTERFACE ${CHOLMOD_INCLUDE_DIR})
    target_link_libraries(tfd::cholmod INTERFACE ${CHOLMOD_LIBRARY})
    target_compile_definitions(tfd::cholmod INTERFACE TFD_HAVE_CHOLMOD)
  else()
    message(STATUS "CHOLMOD not found (libsuitesparse-dev): propagate_bench is built without "
                   "its CHOLMOD baseline")
  endif()
endif()
