# Warnings for our own code only: third-party headers come in as SYSTEM includes.
function(tierlift_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(TIERLIFT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  # GCC 12 at -O3 (the Release build) reports -Wrestrict on libstdc++'s own inlined string
  # code wherever a literal is prepended to a temporary string ("a" + std::string(...)): GCC
  # bug 105651, fixed in GCC 13. The warning stays on in every other build and compiler, where
  # it is not a false positive.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-Wno-restrict>)
  endif()
endfunction()

# tierlift_library(NAME <target> SOURCES ... DEPS ...)
# A module library with its public headers under <module>/include.
function(tierlift_library)
  cmake_parse_arguments(TL "" "NAME" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(${TL_NAME} STATIC ${TL_SOURCES})
  target_include_directories(${TL_NAME} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(${TL_NAME} PUBLIC ${TL_DEPS} PRIVATE ${TL_PRIVATE_DEPS})
  tierlift_warnings(${TL_NAME})
endfunction()

# tierlift_test(NAME <exe> DIR <folder of *.cpp> DEPS ...)
# One GoogleTest executable per test folder; every TEST is registered with ctest.
function(tierlift_test)
  cmake_parse_arguments(TL "" "NAME;DIR" "DEPS" ${ARGN})
  file(GLOB _srcs CONFIGURE_DEPENDS ${TL_DIR}/*.cpp)
  if(NOT _srcs)
    return()
  endif()
  add_executable(${TL_NAME} ${_srcs})
  target_link_libraries(${TL_NAME} PRIVATE ${TL_DEPS} GTest::gtest GTest::gtest_main GTest::gmock)
  target_include_directories(${TL_NAME} PRIVATE ${PROJECT_SOURCE_DIR}/tests/common)
  target_compile_definitions(${TL_NAME} PRIVATE
    TIERLIFT_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    TIERLIFT_SHARED_DIR="${PROJECT_SOURCE_DIR}/../shared"
    TIERLIFT_CLI_PATH="$<TARGET_FILE:tierlift>")
  tierlift_warnings(${TL_NAME})
  include(GoogleTest)
  gtest_discover_tests(${TL_NAME} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 600)
endfunction()
