# The FMUs' sources in one shared object, the way an importer combines source-code FMUs (tests/c:
# test_combined_fmus, test_combined_fmi3_fmus, combined_*_symbols_*). Each FMU's sources are
# compiled with its own -DFMI2_FUNCTION_PREFIX against the FMI 2.0.0 form of the headers (const
# callback members, the prefix applied), made from FMI2_HEADERS_DIR at build time, and again
# under FMI3_FUNCTION_PREFIX with the FMI 3.0 layer. This also compiles every FMU source against
# both header versions. Included from fmu_src/CMakeLists.txt after the models.
set(FMI200_DIR ${CMAKE_CURRENT_BINARY_DIR}/fmi2_2.0.0)
set(FMI200_SCRIPT ${CMAKE_SOURCE_DIR}/tests/c/fmi2_headers_2_0_0.cmake)
add_custom_command(OUTPUT ${FMI200_DIR}/fmi2Functions.h ${FMI200_DIR}/fmi2FunctionTypes.h ${FMI200_DIR}/fmi2TypesPlatform.h
  COMMAND ${CMAKE_COMMAND} -DIN=${FMI2_HEADERS_DIR} -DOUT=${FMI200_DIR} -P ${FMI200_SCRIPT}
  DEPENDS ${FMI200_SCRIPT} ${FMI2_HEADERS_DIR}/fmi2Functions.h ${FMI2_HEADERS_DIR}/fmi2FunctionTypes.h
  COMMENT "FMI 2.0.0 headers from ${FMI2_HEADERS_DIR}"
  VERBATIM)
add_custom_target(fmi2_headers_2_0_0 DEPENDS ${FMI200_DIR}/fmi2Functions.h)

# every folder of FMU code, as the flat sources/ of a packaged FMU sees them
set(_all_dirs ${RW_PLATFORM_DIR} ${RW_WALL_DIR} ${RW_ENGINE_DIR} ${RW_FMI_DIR} ${RW_MODEL_DIR} ${DG_MODEL_DIR}
    ${BD_MODEL_DIR} ${RW_SUNDIALS_INCLUDE})

function(rw_prefixed_objects TARGET PREFIX)
  add_library(${TARGET} OBJECT ${ARGN} ${FMU_SHARED_SOURCES})
  add_dependencies(${TARGET} fmi2_headers_2_0_0)
  target_compile_definitions(${TARGET} PRIVATE FMI2_FUNCTION_PREFIX=${PREFIX})
  target_include_directories(${TARGET} BEFORE PRIVATE ${FMI200_DIR})
  target_include_directories(${TARGET} PRIVATE ${_all_dirs})
  set_target_properties(${TARGET} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()
rw_prefixed_objects(combined_rw_objects RockingWall_ ${RW_FMU_SOURCES})
rw_prefixed_objects(combined_dg_objects Diaphragm_ ${DG_MODEL_SOURCES})
rw_prefixed_objects(combined_bd_objects Building_ ${BD_MODEL_SOURCES})
add_library(combined_fmus SHARED $<TARGET_OBJECTS:combined_rw_objects> $<TARGET_OBJECTS:combined_dg_objects>
            $<TARGET_OBJECTS:combined_bd_objects>)
target_link_libraries(combined_fmus PRIVATE ${RW_SUNDIALS_STATIC} m)
target_link_options(combined_fmus PRIVATE -Wl,--exclude-libs,ALL -Wl,--no-undefined)

# Both FMUs' sources in one shared object under FMI3_FUNCTION_PREFIX: every external symbol must
# carry the prefix (tests/c: combined_fmi3_symbols_*).
function(rw_prefixed_fmi3_objects TARGET PREFIX)
  add_library(${TARGET} OBJECT ${ARGN} ${FMU3_SHARED_SOURCES})
  target_compile_definitions(${TARGET} PRIVATE FMI3_FUNCTION_PREFIX=${PREFIX})
  target_include_directories(${TARGET} PRIVATE ${_all_dirs} ${FMI3_HEADERS_DIR})
  set_target_properties(${TARGET} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()
rw_prefixed_fmi3_objects(combined_fmi3_rw_objects RockingWall_ ${RW_FMU_SOURCES})
rw_prefixed_fmi3_objects(combined_fmi3_dg_objects Diaphragm_ ${DG_MODEL_SOURCES})
add_library(combined_fmi3_fmus SHARED $<TARGET_OBJECTS:combined_fmi3_rw_objects> $<TARGET_OBJECTS:combined_fmi3_dg_objects>)
target_link_libraries(combined_fmi3_fmus PRIVATE ${RW_SUNDIALS_STATIC} m)
target_link_options(combined_fmi3_fmus PRIVATE -Wl,--exclude-libs,ALL -Wl,--no-undefined)
