include(CMakePackageConfigHelpers)

set(TEXSPLAT_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/texsplat)

set(texsplat_installed_libraries texsplat_scenegraph texsplat_nodes texsplat_octree)
if(TEXSPLAT_WITH_MPI)
    list(APPEND texsplat_installed_libraries texsplat_distributed)
endif()
install(TARGETS ${texsplat_installed_libraries}
        EXPORT texsplatTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(folder scenegraph nodes octree)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}/
            DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/texsplat/${folder}
            FILES_MATCHING PATTERN "*.h"
            PATTERN "detail" EXCLUDE
            PATTERN "distributed" EXCLUDE)
endforeach()
# texsplat::distributed's headers include MPI's: installed with the library only.
if(TEXSPLAT_WITH_MPI)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/nodes/distributed/
            DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/texsplat/nodes/distributed
            FILES_MATCHING PATTERN "*.h")
endif()
# Private headers that public ones include (field value traits behind SFFloat & co., the sensor
# queue's lanes, the voxel access DenseGrid and ExternalGrid share and its statistics, the child
# count behind Octree::child(), the CPU backend's cache-line allocator): installed so the public
# headers compile, still namespace detail. The installed-package test compiles every installed
# header, so a missing one fails there.
foreach(header scenegraph/fields/detail/ValueTraits.h scenegraph/sensors/detail/QueueLane.h
               nodes/volume/detail/ContiguousVoxels.h nodes/volume/detail/StatisticsAccumulator.h
               octree/detail/BitCount.h nodes/render/cpu/detail/CacheLineAllocator.h)
    get_filename_component(folder ${header} DIRECTORY)
    install(FILES ${PROJECT_SOURCE_DIR}/${header}
            DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/texsplat/${folder})
endforeach()
install(EXPORT texsplatTargets NAMESPACE texsplat:: DESTINATION ${TEXSPLAT_INSTALL_CMAKEDIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/texsplatConfig.cmake.in
    ${PROJECT_BINARY_DIR}/texsplatConfig.cmake
    INSTALL_DESTINATION ${TEXSPLAT_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/texsplatConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/texsplatConfig.cmake
              ${PROJECT_BINARY_DIR}/texsplatConfigVersion.cmake
        DESTINATION ${TEXSPLAT_INSTALL_CMAKEDIR})
