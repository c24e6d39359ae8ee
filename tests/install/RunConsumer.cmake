# Script mode (cmake -P): install, configure the consumer against the prefix, build, run.
# The consumer is built with the same compiler and flags (a sanitizer build links its runtime).
file(REMOVE_RECURSE ${SCRATCH_DIR})
set(prefix ${SCRATCH_DIR}/prefix)

function(run_step description)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out
                    ERROR_VARIABLE err)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "${description} failed (${result}):\n${out}\n${err}")
    endif()
    message("${out}")
endfunction()

run_step("install" ${CMAKE_COMMAND} --install ${TEXSPLAT_BINARY_DIR} --prefix ${prefix})
run_step("configure consumer" ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR}
         -B ${SCRATCH_DIR}/build -G ${CONSUMER_GENERATOR} -DCMAKE_PREFIX_PATH=${prefix}
         -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CONSUMER_CXX_COMPILER}
         -DTEXSPLAT_EXAMPLES_DIR=${EXAMPLES_DIR}
         "-DCMAKE_CXX_FLAGS=${CONSUMER_CXX_FLAGS}"
         "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_LINKER_FLAGS}")
run_step("build consumer" ${CMAKE_COMMAND} --build ${SCRATCH_DIR}/build)
run_step("run the render-array example" ${SCRATCH_DIR}/build/render_array
         ${SCRATCH_DIR}/array.png)
run_step("run consumer" ${SCRATCH_DIR}/build/consumer)
