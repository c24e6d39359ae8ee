# One INTERFACE target carries the project's warning flags and language level; every texsplat
# target links it PRIVATE (through BUILD_INTERFACE so it never reaches the installed package).
add_library(texsplat_warnings INTERFACE)
target_compile_features(texsplat_warnings INTERFACE cxx_std_17)
target_compile_options(texsplat_warnings INTERFACE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor>
    $<$<AND:$<BOOL:${TEXSPLAT_WARNINGS_AS_ERRORS}>,$<CXX_COMPILER_ID:GNU,Clang>>:-Werror>)
if(TEXSPLAT_ENABLE_ASSERTS)
    target_compile_definitions(texsplat_warnings INTERFACE TEXSPLAT_ENABLE_ASSERTS)
endif()

# texsplat_add_library(<name> <export-name>): a static or shared texsplat library whose public
# headers are included from the repository root ("scenegraph/Node.h"), installed the same way.
function(texsplat_add_library target export_name)
    add_library(${target})
    add_library(texsplat::${export_name} ALIAS ${target})
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name}
                                               POSITION_INDEPENDENT_CODE ON)
    target_compile_features(${target} PUBLIC cxx_std_17)
    target_include_directories(${target} PUBLIC
        $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
        $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/texsplat>)
    target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:texsplat_warnings>)
endfunction()
