# Installs the built project into a scratch prefix and imports the installed
# Python package from there (PYTHONPATH = PREFIX/INSTALL_DIR, as the README
# says), checking that it is the installed copy and that it renders.
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix"
                OUTPUT_QUIET RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "cmake --install failed: ${rc}")
endif()
set(site "${WORK_DIR}/prefix/${INSTALL_DIR}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${site}" "${PYTHON}" -c
          "import casteljau, sys; assert casteljau.__file__.startswith(sys.argv[1]), casteljau.__file__; a = casteljau.render_svg(b'<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"8\" height=\"4\"><rect width=\"4\" height=\"4\" fill=\"red\"/></svg>'); assert a.shape == (4, 8, 4) and a[0, 0].tolist() == [255, 0, 0, 255], a; print('imported', casteljau.__file__)"
          "${site}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "importing the installed package failed: ${rc}\n${out}${err}")
endif()
message(STATUS "${out}")
