# MDR_LAMMPS: the LAMMPS pair style mdr/visco (dem/lammps) built as a plugin and tested in a minimal LAMMPS
# (GRANULAR + PLUGIN, MPI, shared) that is built once into the build tree from Debian's source package
# (scripts/fetch-lammps-source) with ExternalProject; its stamps keep it from being built again. MDR_LAMMPS_SOURCE
# and MDR_LAMMPS_PREFIX instead name an unpacked LAMMPS source and its installation built that way (a developer's
# cache). Not in the sanitize preset: the tests run in the release build only.
include(ExternalProject)
find_package(MPI REQUIRED COMPONENTS CXX)

set(MDR_LAMMPS_SOURCE "" CACHE PATH "An unpacked LAMMPS source (its src/ and cmake/) to use instead of Debian's")
set(MDR_LAMMPS_PREFIX "" CACHE PATH "The installation of MDR_LAMMPS_SOURCE (LAMMPS_EXCEPTIONS on), not built here")
set(mdr_lammps_options -D CMAKE_BUILD_TYPE=Release -D PKG_GRANULAR=on -D PKG_PLUGIN=on -D BUILD_SHARED_LIBS=on
    -D BUILD_MPI=on -D BUILD_OMP=off -D WITH_JPEG=off -D WITH_PNG=off -D WITH_GZIP=off -D WITH_FFMPEG=off
    -D LAMMPS_EXCEPTIONS=on)
if(MDR_LAMMPS_PREFIX)
  set(mdr_lammps_source ${MDR_LAMMPS_SOURCE})
  set(mdr_lammps_prefix ${MDR_LAMMPS_PREFIX})
  add_custom_target(mdr_lammps)
else()
  set(mdr_lammps_source ${CMAKE_BINARY_DIR}/lammps/source)
  set(mdr_lammps_prefix ${CMAKE_BINARY_DIR}/lammps/install)
  if(MDR_LAMMPS_SOURCE)
    set(mdr_lammps_download ${CMAKE_COMMAND} -E copy_directory ${MDR_LAMMPS_SOURCE} <SOURCE_DIR>)
  else()
    set(mdr_lammps_download ${PROJECT_SOURCE_DIR}/scripts/fetch-lammps-source <SOURCE_DIR>)
  endif()
  ExternalProject_Add(mdr_lammps
    PREFIX ${CMAKE_BINARY_DIR}/lammps
    SOURCE_DIR ${mdr_lammps_source}
    INSTALL_DIR ${mdr_lammps_prefix}
    DOWNLOAD_COMMAND ${mdr_lammps_download}
    UPDATE_COMMAND ""
    SOURCE_SUBDIR cmake
    CMAKE_ARGS ${mdr_lammps_options} -D CMAKE_INSTALL_PREFIX=<INSTALL_DIR> -D CMAKE_INSTALL_LIBDIR=lib
    BUILD_BYPRODUCTS ${mdr_lammps_prefix}/lib/liblammps.so
    EXCLUDE_FROM_ALL OFF)
endif()

add_library(mdrviscoplugin MODULE dem/lammps/pair_mdr_visco.cpp dem/lammps/mdr_visco_plugin.cpp)
target_include_directories(mdrviscoplugin PRIVATE ${mdr_lammps_source}/src ${mdr_lammps_source}/src/PLUGIN)
target_compile_definitions(mdrviscoplugin PRIVATE LAMMPS_EXCEPTIONS LAMMPS_SMALLBIG)
target_link_libraries(mdrviscoplugin PRIVATE mdr::core MPI::MPI_CXX ${mdr_lammps_prefix}/lib/liblammps.so)
set_target_properties(mdrviscoplugin PROPERTIES PREFIX "")
# mdr's functions in the plugin are the plugin's own: bound inside it (no calls through the PLT; the static library's
# symbols hidden) and, within a file, inlined where GCC would (not interposable).
target_compile_options(mdrviscoplugin PRIVATE -fno-semantic-interposition)
target_link_options(mdrviscoplugin PRIVATE -Wl,--exclude-libs,ALL)
# every symbol resolved at the link (mdr, LAMMPS, MPI), not first at `plugin load`; not with the sanitizers, whose
# runtime clang leaves to the executable
if(NOT MDR_SANITIZE)
  target_link_options(mdrviscoplugin PRIVATE -Wl,--no-undefined)
endif()
add_dependencies(mdrviscoplugin mdr_lammps)
set(MDR_LAMMPS_BINARY ${mdr_lammps_prefix}/bin/lmp)
set(MDR_LAMMPS_LIBRARY_DIR ${mdr_lammps_prefix}/lib)
