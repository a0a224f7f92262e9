# Re-extracts the strings from the current sources into copies of the .ts files, so a string
# added without a translation fails here, then checks the copies.
file(GLOB TS_FILES "${TS_DIR}/*.ts")
foreach(ts IN LISTS TS_FILES)
    get_filename_component(name "${ts}" NAME)
    configure_file("${ts}" "${WORK_DIR}/${name}" COPYONLY)
    execute_process(COMMAND "${LUPDATE}" -silent -no-obsolete -locations none
                            -I "${SOURCE_DIR}/core" -I "${SOURCE_DIR}/ui"
                            "@${SOURCES_LIST}" -ts "${WORK_DIR}/${name}"
                    RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "lupdate failed on ${name}")
    endif()
    list(APPEND copies "${WORK_DIR}/${name}")
endforeach()
execute_process(COMMAND "${CHECKER}" ${copies} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "translations are incomplete: run `cmake --build build --target update_translations` and translate what is marked unfinished")
endif()
