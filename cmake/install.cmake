# What `cmake --install` and `cpack -G DEB` put where (docs/cpp.md, docs/python.md):
#   bin/mdr                                  the command line
#   lib/libmdr_core.a, libmdr_io.a, libmdr_fit.a, libmdr_fitcase.a  the library (static: see docs/cpp.md)
#   include/mdr/...                          the public headers
#   lib/cmake/mdr/                           the CMake package: find_package(mdr) gives mdr::core and mdr::io
#                                            (mdrTargets.cmake), COMPONENTS fit adds mdr::fit and mdr::fitcase
#                                            (mdrFitTargets.cmake)
#   lib/python3/dist-packages/mdr/           the Python package (with MDR_BUILD_PYTHON; python/CMakeLists.txt)
include(CMakePackageConfigHelpers)

set(MDR_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/mdr CACHE STRING
    "Where the CMake package (mdrConfig.cmake) is installed, relative to the prefix")

install(TARGETS mdr RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS mdr_core mdr_io EXPORT mdrTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# mdr::fit links Ceres: its own export set, loaded only for find_package(mdr COMPONENTS fit) (mdrConfig.cmake.in).
# mdr::fitcase (fit cases: mdr::io and mdr::fit together) needs what both need, so it is in that set; it links
# mdr_instrument (the instrument readers) and through it libzip and libdeflate (Debian: libzip-dev, libdeflate-dev).
install(TARGETS mdr_fit mdr_fitcase mdr_instrument mdr_libzip mdr_libdeflate EXPORT mdrFitTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY include/mdr DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
install(EXPORT mdrTargets NAMESPACE mdr:: FILE mdrTargets.cmake DESTINATION ${MDR_INSTALL_CMAKEDIR})
install(EXPORT mdrFitTargets NAMESPACE mdr:: FILE mdrFitTargets.cmake DESTINATION ${MDR_INSTALL_CMAKEDIR})
configure_package_config_file(cmake/mdrConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/mdrConfig.cmake
                              INSTALL_DESTINATION ${MDR_INSTALL_CMAKEDIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/mdrConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/mdrConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/mdrConfigVersion.cmake
        DESTINATION ${MDR_INSTALL_CMAKEDIR})

# cpack -G DEB: one package with all of the above under /usr. Depends: the shared libraries that the binary and
# the extension load, found by dpkg-shlibdeps (libfmt9, libstdc++6, libc6, libzip4 and libdeflate0
# for the extension's instrument readers, ...; Debian's Ceres CMake package links
# libceres.a, so no libceres3 but Ceres' own shared libraries: glog, CHOLMOD, CXSparse, LAPACK, ATLAS) and the
# Python the extension was built for. Building against the library: find_package(mdr) needs fmt's CMake files
# (libfmt-dev, recommended); COMPONENTS fit needs Ceres' (libceres-dev, suggested) (docs/cpp.md).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME mdr)
set(CPACK_PACKAGE_VENDOR "mdr developers")
set(CPACK_PACKAGE_CONTACT "mdr developers <mdr@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "viscoelastic contact mechanics by the Method of Dimensionality Reduction")
set(CPACK_PACKAGE_DESCRIPTION
    "A C++20 library (static, with its CMake package), a command line driven by TOML case files, and a Python package over the same core.")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libfmt-dev")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libceres-dev")
if(MDR_BUILD_PYTHON)
  # The extension is built for one Python minor version (its file name says which).
  math(EXPR next_minor "${MDR_PYTHON_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3 (>= ${MDR_PYTHON_VERSION_MAJOR}.${MDR_PYTHON_VERSION_MINOR}~), \
python3 (<< ${MDR_PYTHON_VERSION_MAJOR}.${next_minor}~), python3-numpy")
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libfmt-dev, python3-matplotlib")
  set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libceres-dev, python3-distributed, python3-h5py")  # Dask batches, HDF5 stacks
endif()
include(CPack)
