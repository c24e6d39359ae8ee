# Every dependency comes from Debian 12's packages (see docs/building.md). Optional parts are
# looked up only when their TEXSPLAT_WITH_* option is on.
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)
find_package(glm REQUIRED)
# The CPU splat backend: Highway for SIMD with run-time dispatch (one binary uses AVX2 or
# AVX-512 where present), oneTBB for its threads (OpenVDB already depends on it).
find_package(hwy REQUIRED)
find_package(TBB REQUIRED)
# zlib: the gzip encoding of NRRD volumes (it comes with OpenVDB, OpenEXR and Boost anyway).
find_package(ZLIB REQUIRED)
if(TEXSPLAT_WITH_GL)
    pkg_check_modules(epoxy REQUIRED IMPORTED_TARGET GLOBAL epoxy)
    pkg_check_modules(egl REQUIRED IMPORTED_TARGET GLOBAL egl)
endif()

if(TEXSPLAT_WITH_OPENVDB)
    # Debian's OpenVDB 10 ships its Find module, not a config package; it also needs Boost
    # iostreams, which must be installed (libboost-iostreams-dev) or configuration fails.
    list(APPEND CMAKE_MODULE_PATH /usr/lib/x86_64-linux-gnu/cmake/OpenVDB)
    # FindOpenVDB.cmake sets BUILD_SHARED_LIBS ON for its caller; keep the user's choice.
    set(texsplat_shared_libs ${BUILD_SHARED_LIBS})
    find_package(OpenVDB REQUIRED)
    set(BUILD_SHARED_LIBS ${texsplat_shared_libs})
endif()
if(TEXSPLAT_WITH_MPI)
    # Debian's OpenMPI (libopenmpi-dev): FindMPI finds its compiler wrappers and makes MPI::MPI_CXX.
    find_package(MPI REQUIRED COMPONENTS CXX)
endif()
if(TEXSPLAT_WITH_NETCDF)
    # Debian's libnetcdf-dev ships a config package (target netCDF::netcdf, the C library).
    find_package(netCDF REQUIRED)
endif()
if(TEXSPLAT_WITH_GLTF)
    find_package(TinyGLTF REQUIRED)
endif()
if(TEXSPLAT_WITH_EXR)
    find_package(OpenEXR REQUIRED)
endif()
if(TEXSPLAT_BUILD_APPS)
    find_package(CLI11 REQUIRED)
    pkg_check_modules(stb REQUIRED IMPORTED_TARGET GLOBAL stb)
endif()
# The font of labels drawn into images, such as the colour legend's (Debian: fonts-dejavu-core).
# Without it labels use the built-in bitmap font, with a warning at run time.
find_file(TEXSPLAT_LABEL_FONT_FILE DejaVuSans.ttf
    PATHS /usr/share/fonts/truetype/dejavu /usr/share/fonts/TTF /usr/share/fonts/dejavu
    DOC "TrueType font of the labels drawn into images")
if(NOT TEXSPLAT_LABEL_FONT_FILE)
    message(STATUS "DejaVuSans.ttf not found (Debian: fonts-dejavu-core): image labels will use "
                   "the built-in bitmap font")
endif()
if(TEXSPLAT_WITH_VIEWER AND TEXSPLAT_BUILD_APPS)
    find_package(glfw3 REQUIRED)
    pkg_check_modules(imgui REQUIRED IMPORTED_TARGET GLOBAL imgui)
endif()
if(TEXSPLAT_BUILD_TESTS)
    find_package(GTest REQUIRED)
endif()
if(TEXSPLAT_BUILD_BENCHMARKS)
    find_package(benchmark REQUIRED)
endif()
