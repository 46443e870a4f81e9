# The FMI 3.0 FMUs: build/fmi3/RockingWall.fmu, Diaphragm.fmu and Building.fmu, Model Exchange and
# Co-Simulation. The same models (callbacks of fmu_model.h) and the same core (fmu_core.c,
# cs_cvode.c) as the FMI 2.0 FMUs, under the FMI 3.0 layer fmi3Functions.c. Included from
# fmu_src/CMakeLists.txt after the FMI 2.0 FMUs, whose variables (SUNDIALS, glibc options, model
# sources) it uses.
#
# FMI 3.0 headers: the ones fmpy ships next to the FMI 2.0 headers (FMI2_HEADERS_DIR, found by
# the top-level CMakeLists.txt), unless FMI3_HEADERS_DIR points elsewhere.
if(NOT FMI3_HEADERS_DIR)
  set(FMI3_HEADERS_DIR "${FMI2_HEADERS_DIR}" CACHE PATH "Folder holding fmi3Functions.h")
endif()
if(NOT EXISTS "${FMI3_HEADERS_DIR}/fmi3Functions.h")
  message(FATAL_ERROR "fmi3Functions.h not found in FMI3_HEADERS_DIR=${FMI3_HEADERS_DIR}")
endif()
message(STATUS "FMI 3.0 headers: ${FMI3_HEADERS_DIR}")

set(FMU3_SHARED_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/fmi3Functions.c
  ${CMAKE_CURRENT_SOURCE_DIR}/fmu_core.c
  ${CMAKE_CURRENT_SOURCE_DIR}/cs_cvode.c)
set(FMU3_DIR ${CMAKE_BINARY_DIR}/fmi3)

# rw_add_fmu3(NAME XML BUILD_XML SOURCES... HEADERS...): the binary NAME.so (target NAME_fmi3, only
# the fmi3* API exported) and the packaged ${CMAKE_BINARY_DIR}/fmi3/NAME.fmu with its sources and
# their sources/buildDescription.xml (the FMI 3.0 place of the source file list; cs_none.c
# stands in for cs_cvode.c there, as in the FMI 2.0 source FMUs).
function(rw_add_fmu3 NAME XML BUILD_XML)
  cmake_parse_arguments(F "" "" "SOURCES;HEADERS" ${ARGN})
  set(target ${NAME}_fmi3)
  add_library(${target} SHARED ${F_SOURCES} ${FMU3_SHARED_SOURCES} ${FMU_BINARY_ONLY_SOURCES})
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${FMI3_HEADERS_DIR})
  target_link_libraries(${target} PRIVATE ${RW_SUNDIALS_STATIC} m)
  target_link_options(${target} PRIVATE -Wl,--exclude-libs,ALL -Wl,--no-undefined ${FMU_GLIBC_LINK_OPTIONS})
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    OUTPUT_NAME ${NAME}
    C_VISIBILITY_PRESET hidden
    LIBRARY_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/fmi3)
  set(fmu ${FMU3_DIR}/${NAME}.fmu)
  set(stage ${CMAKE_CURRENT_BINARY_DIR}/${NAME}_fmi3_stage)
  set(headers ${FMU_SHARED_HEADERS} ${FMI3_HEADERS_DIR}/fmi3Functions.h ${FMI3_HEADERS_DIR}/fmi3FunctionTypes.h
      ${FMI3_HEADERS_DIR}/fmi3PlatformTypes.h)
  add_custom_command(OUTPUT ${fmu}
    COMMAND ${CMAKE_COMMAND} -E remove_directory ${stage}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${stage}/binaries/x86_64-linux ${stage}/sources ${FMU3_DIR}
    COMMAND ${CMAKE_COMMAND} -E copy ${XML} ${stage}/modelDescription.xml
    COMMAND ${CMAKE_COMMAND} -E copy ${BUILD_XML} ${stage}/sources/buildDescription.xml
    COMMAND ${CMAKE_COMMAND} -E copy $<TARGET_FILE:${target}> ${stage}/binaries/x86_64-linux/${NAME}.so
    COMMAND ${CMAKE_COMMAND} -E copy ${F_SOURCES} ${F_HEADERS} ${FMU3_SHARED_SOURCES} ${headers}
            ${CMAKE_SOURCE_DIR}/fmu_src/cs_none.c ${stage}/sources/
    COMMAND ${CMAKE_COMMAND} -E remove -f ${fmu}
    COMMAND ${CMAKE_COMMAND} -E chdir ${stage}
            ${CMAKE_COMMAND} -E tar cf ${fmu} --format=zip modelDescription.xml binaries sources
    DEPENDS ${target} ${XML} ${BUILD_XML} ${CMAKE_SOURCE_DIR}/fmu_src/cs_none.c ${F_SOURCES} ${F_HEADERS}
            ${FMU3_SHARED_SOURCES} ${headers}
    COMMENT "Packaging ${fmu}"
    VERBATIM)
  add_custom_target(${NAME}_fmi3_fmu ALL DEPENDS ${fmu})
endfunction()

set(FMI3_XML_DIR ${CMAKE_CURRENT_SOURCE_DIR}/fmi3)
rw_add_fmu3(RockingWall ${FMI3_XML_DIR}/RockingWall/modelDescription.xml
  ${FMI3_XML_DIR}/RockingWall/buildDescription.xml
  SOURCES ${RW_MODEL_SOURCES} HEADERS ${RW_MODEL_HEADERS})
rw_add_fmu3(Diaphragm ${FMI3_XML_DIR}/Diaphragm/modelDescription.xml
  ${FMI3_XML_DIR}/Diaphragm/buildDescription.xml
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/diaphragm/diaphragm_model.c
  HEADERS ${CMAKE_CURRENT_SOURCE_DIR}/diaphragm/diaphragm_variables.h)
target_include_directories(Diaphragm_fmi3 PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/diaphragm)
rw_add_fmu3(Building ${FMI3_XML_DIR}/Building/modelDescription.xml
  ${FMI3_XML_DIR}/Building/buildDescription.xml
  SOURCES ${BD_MODEL_SOURCES} HEADERS ${BD_MODEL_HEADERS})
target_include_directories(Building_fmi3 PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/building)

# both FMUs under the FMI 3.0 layer as static libraries, for the C tests of fmi3Functions.c
add_library(rw_fmi3_static STATIC rw_model.c cs_exact.c ${RW_ENGINE_SOURCES} ${FMU3_SHARED_SOURCES})
target_include_directories(rw_fmi3_static PUBLIC ${CMAKE_CURRENT_SOURCE_DIR} ${FMI3_HEADERS_DIR})
target_link_libraries(rw_fmi3_static PUBLIC rw_physics ${RW_SUNDIALS_STATIC})
add_library(dg_fmi3_static STATIC diaphragm/diaphragm_model.c ${FMU3_SHARED_SOURCES})
target_include_directories(dg_fmi3_static PUBLIC ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/diaphragm
                           ${FMI3_HEADERS_DIR})
target_link_libraries(dg_fmi3_static PUBLIC ${RW_SUNDIALS_STATIC} m)

# Both FMUs' sources in one shared object under FMI3_FUNCTION_PREFIX, the way an importer combines
# source-code FMUs: every external symbol must carry the prefix (tests/c: combined_fmi3_symbols_*).
if(RW_BUILD_TESTS)
  function(rw_prefixed_fmi3_objects TARGET PREFIX)
    add_library(${TARGET} OBJECT ${ARGN} ${FMU3_SHARED_SOURCES})
    target_compile_definitions(${TARGET} PRIVATE FMI3_FUNCTION_PREFIX=${PREFIX})
    target_include_directories(${TARGET} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/diaphragm
                               ${FMI3_HEADERS_DIR} ${RW_SUNDIALS_INCLUDE})
    set_target_properties(${TARGET} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  endfunction()
  rw_prefixed_fmi3_objects(combined_fmi3_rw_objects RockingWall_ ${RW_MODEL_SOURCES})
  rw_prefixed_fmi3_objects(combined_fmi3_dg_objects Diaphragm_ ${CMAKE_CURRENT_SOURCE_DIR}/diaphragm/diaphragm_model.c)
  add_library(combined_fmi3_fmus SHARED $<TARGET_OBJECTS:combined_fmi3_rw_objects> $<TARGET_OBJECTS:combined_fmi3_dg_objects>)
  target_link_libraries(combined_fmi3_fmus PRIVATE ${RW_SUNDIALS_STATIC} m)
  target_link_options(combined_fmi3_fmus PRIVATE -Wl,--exclude-libs,ALL -Wl,--no-undefined)
endif()
