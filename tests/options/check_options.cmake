# Builds app.c against the compiled library (LIB) with the library's own
# options, which must link and run, then with each layout option changed,
# which must fail to link with the option named in the linker's message.
# cmake -DCC=... -DFLAGS=... -DINC=... -DLIB=... -DSRC=... -DOUT=... [-DEMU=qemu-...] -P check_options.cmake
separate_arguments(flags UNIX_COMMAND "${FLAGS}")

function(build result output)
  execute_process(COMMAND ${CC} -std=c99 ${flags} -I${INC} ${ARGN} ${SRC} ${LIB} -lm -o ${OUT}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${result} ${rc} PARENT_SCOPE)
  set(${output} "${out}${err}" PARENT_SCOPE)
endfunction()

build(rc msg)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the library's own options do not link:\n${msg}")
endif()
execute_process(COMMAND ${EMU} ${OUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "init failed with the library's own options: ${out}")
endif()
message(STATUS "same options: ${out}")

foreach(case XF_PACKET_MAX_LEN=84 XF_PARSER_SLOTS=2 XF_CLIENT_QUEUE=2 XF_CLIENT_RESULTS=3)
  string(REPLACE "=" "_is_" symbol "xf_option_${case}")
  build(rc msg -D${case})
  if(rc EQUAL 0)
    message(FATAL_ERROR "-D${case}: linked against a library built with other options")
  endif()
  string(REGEX MATCH "undefined (reference to|symbol)[^\n]*${symbol}[^\n]*" line "${msg}")
  if(NOT line)
    message(FATAL_ERROR "-D${case}: the link failed without naming ${symbol}:\n${msg}")
  endif()
  message(STATUS "-D${case}: link refused: ${line}")
endforeach()
