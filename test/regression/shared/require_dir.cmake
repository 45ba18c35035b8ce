# cmake -DDIR=... -P require_dir.cmake: fails (non-zero exit, one line naming the path) when DIR is missing.
if(NOT IS_DIRECTORY "${DIR}")
  message(FATAL_ERROR "reference data missing: ${DIR} (clone the shared data beside the repository as "
    "../shared, or configure with -DPERIFORGE_SHARED_DIR=...); the tests that compare against it fail")
endif()
message(STATUS "reference data present: ${DIR}")
