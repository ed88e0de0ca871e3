# Replay of the fuzz harnesses' saved inputs in plain ctest: included by tests/CMakeLists.txt
# (so any compiler, no libFuzzer; built whenever the tests are).
#
# replay_<harness><suffix> is the harness with fuzz/replay_main.c for a main(): it calls
# LLVMFuzzerTestOneInput on every file of fuzz/corpus/<harness>/ and fuzz/regressions/<harness>/,
# listed when the test runs (a new reproducer dropped there is replayed by the next ctest, no
# cmake run needed). One test per harness and variant (fuzz/variants.cmake).
include(${PROJECT_SOURCE_DIR}/fuzz/variants.cmake)

foreach(_xf_h ${XFGCU_FUZZ_HARNESSES})
  foreach(_xf_v ${XFGCU_FUZZ_VARIANTS})
    set(_xf_t replay_${_xf_h}${XFGCU_FUZZ_SUFFIX_${_xf_v}})
    add_executable(${_xf_t} ${PROJECT_SOURCE_DIR}/fuzz/${_xf_h}.c ${PROJECT_SOURCE_DIR}/fuzz/replay_main.c)
    target_link_libraries(${_xf_t} PRIVATE xfgcu::headers xfgcu_dev_flags)
    target_include_directories(${_xf_t} PRIVATE ${PROJECT_SOURCE_DIR}/tests) # parser_ref.h
    # replay_main.c includes no xfgcu header: the definitions only matter to the harness
    target_compile_definitions(${_xf_t} PRIVATE XF_IMPLEMENTATION ${XFGCU_FUZZ_DEFS_${_xf_v}})
    add_test(NAME ${_xf_t} COMMAND ${_xf_t} ${PROJECT_SOURCE_DIR}/fuzz/corpus/${_xf_h}
                                            ${PROJECT_SOURCE_DIR}/fuzz/regressions/${_xf_h})
    set_tests_properties(${_xf_t} PROPERTIES TIMEOUT 120 LABELS fuzz-replay)
  endforeach()
endforeach()
