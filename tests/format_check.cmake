# ctest "clang_format": every C++ file of ours must already be in clang-format's form
# (.clang-format at the root). Run `clang-format -i` on the files it names.
file(GLOB_RECURSE _files
  ${ROOT}/ir/*.cpp ${ROOT}/ir/*.h ${ROOT}/assembly/*.cpp ${ROOT}/assembly/*.h
  ${ROOT}/codegen/*.cpp ${ROOT}/codegen/*.h ${ROOT}/runtime/*.cpp ${ROOT}/runtime/*.h ${ROOT}/effects/*.cpp ${ROOT}/effects/*.h
  ${ROOT}/listings/*.cpp ${ROOT}/listings/*.h ${ROOT}/cli/*.cpp ${ROOT}/cli/*.h
  ${ROOT}/io/*.cpp ${ROOT}/io/*.h ${ROOT}/corpus/*.cpp ${ROOT}/corpus/*.h
  ${ROOT}/generate/*.cpp ${ROOT}/generate/*.h ${ROOT}/glsl/*.cpp ${ROOT}/glsl/*.h
  ${ROOT}/tests/*.cpp ${ROOT}/tests/*.h ${ROOT}/bench/*.cpp ${ROOT}/bench/*.h)
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${_files}
  RESULT_VARIABLE _rc ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "files not in clang-format's form:\n${_err}")
endif()
