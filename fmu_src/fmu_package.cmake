# A model's FMUs: rw_add_fmu (FMI 2.0: build/NAME.fmu) and rw_add_fmu3 (FMI 3.0: build/fmi3/NAME.fmu),
# Model Exchange and Co-Simulation. Each binary is the model's object libraries (OBJECTS) over
# the FMI layer's (fmi/: the API layer, fmu_core.c, cs_cvode.c) and platform/glibc_compat.c; the
# packaged sources/ holds the model's files (SOURCES, HEADERS) and the layer's, flat, with
# cs_without_cvode.c in place of cs_cvode.c, so that an importer rebuilds the FMU without SUNDIALS
# (the <SourceFiles> of <ModelExchange>, FMI 3.0's sources/buildDescription.xml). Included from
# fmu_src/CMakeLists.txt after wall/, engine/ and fmi/, whose variables it uses.

# rw_fmu_binary(TARGET OUTPUT_NAME OUTPUT_DIR LAYER OBJECTS...): the shared library, no "lib"
# prefix, only the API exported
function(rw_fmu_binary TARGET OUTPUT_NAME OUTPUT_DIR LAYER)
  add_library(${TARGET} SHARED ${FMU_BINARY_ONLY_SOURCES})
  target_link_libraries(${TARGET} PRIVATE ${ARGN} ${LAYER} fmu_core_objects fmu_cvode_objects ${RW_SUNDIALS_STATIC} m)
  target_link_options(${TARGET} PRIVATE -Wl,--exclude-libs,ALL -Wl,--no-undefined ${FMU_GLIBC_LINK_OPTIONS})
  set_target_properties(${TARGET} PROPERTIES
    PREFIX ""
    OUTPUT_NAME ${OUTPUT_NAME}
    C_VISIBILITY_PRESET hidden
    LIBRARY_OUTPUT_DIRECTORY ${OUTPUT_DIR})
endfunction()

# rw_add_fmu(NAME XML OBJECTS... SOURCES... HEADERS...): the binary NAME.so (target NAME) and the
# packaged ${CMAKE_BINARY_DIR}/NAME.fmu with its sources
function(rw_add_fmu NAME XML)
  cmake_parse_arguments(F "" "" "OBJECTS;SOURCES;HEADERS" ${ARGN})
  rw_fmu_binary(${NAME} ${NAME} ${RW_FMU_BINARY_DIR} fmi2_layer ${F_OBJECTS})
  set(fmu ${CMAKE_BINARY_DIR}/${NAME}.fmu)
  set(stage ${RW_FMU_BINARY_DIR}/${NAME}_stage)
  set(win64_copy "")
  set(win64_depends "")
  if(RW_WIN64)
    set(win64_copy COMMAND ${CMAKE_COMMAND} -E make_directory ${stage}/binaries/win64
                   COMMAND ${CMAKE_COMMAND} -E copy ${RW_WIN64_BINARY_DIR}/${NAME}.dll ${stage}/binaries/win64/${NAME}.dll)
    set(win64_depends rw_win64 ${RW_WIN64_BINARY_DIR}/${NAME}.dll)
  endif()
  add_custom_command(OUTPUT ${fmu}
    COMMAND ${CMAKE_COMMAND} -E remove_directory ${stage}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${stage}/binaries/linux64 ${stage}/sources
    COMMAND ${CMAKE_COMMAND} -E copy ${XML} ${stage}/modelDescription.xml
    COMMAND ${CMAKE_COMMAND} -E copy $<TARGET_FILE:${NAME}> ${stage}/binaries/linux64/${NAME}.so
    ${win64_copy}
    COMMAND ${CMAKE_COMMAND} -E copy ${F_SOURCES} ${F_HEADERS} ${FMU_SHARED_SOURCES} ${FMU_SHARED_HEADERS}
            ${FMU_WITHOUT_CVODE_SOURCE} ${stage}/sources/
    COMMAND ${CMAKE_COMMAND} -E remove -f ${fmu}
    COMMAND ${CMAKE_COMMAND} -E chdir ${stage}
            ${CMAKE_COMMAND} -E tar cf ${fmu} --format=zip modelDescription.xml binaries sources
    DEPENDS ${NAME} ${win64_depends} ${XML} ${FMU_WITHOUT_CVODE_SOURCE} ${F_SOURCES} ${F_HEADERS} ${FMU_SHARED_SOURCES}
            ${FMU_SHARED_HEADERS}
    COMMENT "Packaging ${fmu}"
    VERBATIM)
  add_custom_target(${NAME}_fmu ALL DEPENDS ${fmu})
endfunction()

# rw_add_fmu3(NAME XML BUILD_XML OBJECTS... SOURCES... HEADERS...): the binary NAME.so (target
# NAME_fmi3, only the fmi3* API exported) and the packaged ${CMAKE_BINARY_DIR}/fmi3/NAME.fmu with its
# sources and their sources/buildDescription.xml (the FMI 3.0 place of the source file list)
set(FMU3_DIR ${CMAKE_BINARY_DIR}/fmi3)
function(rw_add_fmu3 NAME XML BUILD_XML)
  cmake_parse_arguments(F "" "" "OBJECTS;SOURCES;HEADERS" ${ARGN})
  set(target ${NAME}_fmi3)
  rw_fmu_binary(${target} ${NAME} ${RW_FMU_BINARY_DIR}/fmi3 fmi3_layer ${F_OBJECTS})
  set(fmu ${FMU3_DIR}/${NAME}.fmu)
  set(stage ${RW_FMU_BINARY_DIR}/${NAME}_fmi3_stage)
  set(headers ${FMU_SHARED_HEADERS} ${FMI3_HEADERS_DIR}/fmi3Functions.h ${FMI3_HEADERS_DIR}/fmi3FunctionTypes.h
      ${FMI3_HEADERS_DIR}/fmi3PlatformTypes.h)
  add_custom_command(OUTPUT ${fmu}
    COMMAND ${CMAKE_COMMAND} -E remove_directory ${stage}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${stage}/binaries/x86_64-linux ${stage}/sources ${FMU3_DIR}
    COMMAND ${CMAKE_COMMAND} -E copy ${XML} ${stage}/modelDescription.xml
    COMMAND ${CMAKE_COMMAND} -E copy ${BUILD_XML} ${stage}/sources/buildDescription.xml
    COMMAND ${CMAKE_COMMAND} -E copy $<TARGET_FILE:${target}> ${stage}/binaries/x86_64-linux/${NAME}.so
    COMMAND ${CMAKE_COMMAND} -E copy ${F_SOURCES} ${F_HEADERS} ${FMU3_SHARED_SOURCES} ${headers}
            ${FMU_WITHOUT_CVODE_SOURCE} ${stage}/sources/
    COMMAND ${CMAKE_COMMAND} -E remove -f ${fmu}
    COMMAND ${CMAKE_COMMAND} -E chdir ${stage}
            ${CMAKE_COMMAND} -E tar cf ${fmu} --format=zip modelDescription.xml binaries sources
    DEPENDS ${target} ${XML} ${BUILD_XML} ${FMU_WITHOUT_CVODE_SOURCE} ${F_SOURCES} ${F_HEADERS}
            ${FMU3_SHARED_SOURCES} ${headers}
    COMMENT "Packaging ${fmu}"
    VERBATIM)
  add_custom_target(${NAME}_fmi3_fmu ALL DEPENDS ${fmu})
endfunction()

# rw_add_fmus(NAME OBJECTS... SOURCES... HEADERS...): both FMUs of the model in the current folder,
# from its fmi2/modelDescription.xml, fmi3/modelDescription.xml and fmi3/buildDescription.xml
function(rw_add_fmus NAME)
  set(d ${CMAKE_CURRENT_SOURCE_DIR})
  rw_add_fmu(${NAME} ${d}/fmi2/modelDescription.xml ${ARGN})
  rw_add_fmu3(${NAME} ${d}/fmi3/modelDescription.xml ${d}/fmi3/buildDescription.xml ${ARGN})
endfunction()
