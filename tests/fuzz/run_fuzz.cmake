# One short run of a fuzz target, the same inputs tried on every run: the corpus it adds to
# (WORK/corpus) is emptied first, so that only the kept inputs and the collected seeds (INPUTS)
# start it, and -seed fixes the mutations. A crash's input goes to WORK/ (libFuzzer says where).
#   cmake -DFUZZER=<target> -DWORK=<folder> -DINPUTS=<dir>|<dir>... -DOPTIONS=<flag>|<flag>...
#         -P run_fuzz.cmake
string(REPLACE "|" ";" inputs "${INPUTS}")
string(REPLACE "|" ";" options "${OPTIONS}")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/corpus")
set(existing "")
foreach(dir IN LISTS inputs)
    if(IS_DIRECTORY "${dir}")
        list(APPEND existing "${dir}")
    endif()
endforeach()
execute_process(COMMAND "${FUZZER}" ${options} "-artifact_prefix=${WORK}/" "${WORK}/corpus"
                        ${existing}
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "${FUZZER} failed (${result}): its report is above")
endif()
