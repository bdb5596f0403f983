# The tests of the editor (issue 27; doc/editor.md), included by tools/fair-curves/CMakeLists.txt
# inside if(FAIR_BUILD_TESTS):
#   editor_api      the API and every bad input against the program run directly (Python 3 stdlib)
#   editor_load     8 clients x 40 requests, every answer the program's; latency percentiles
#   editor_page_units  the page's modules in Node: curve evaluation, point files, outcome words,
#                   request channels
#   editor_browser  the page in Debian's headless chromium driven by puppeteer-core
#                   (test/editor/package-lock.json; `npm ci` in test/editor, done by
#                   `bash tools/bootstrap.sh test`)
# A test whose tools are missing exits 77 (skipped), unless FAIR_EDITOR_REQUIRE_BROWSER=1 in the
# environment (bootstrap's test command sets it: in CI they must run).
set(FAIR_EDITOR_TEST_DIR ${CMAKE_CURRENT_LIST_DIR})
if(EXISTS /usr/bin/python3)
  set(FAIR_EDITOR_PYTHON /usr/bin/python3)
else()
  find_program(FAIR_EDITOR_PYTHON python3)
endif()
find_program(FAIR_EDITOR_NODE node)

if(FAIR_EDITOR_PYTHON)
  add_test(NAME editor_api COMMAND ${FAIR_EDITOR_PYTHON} ${FAIR_EDITOR_TEST_DIR}/editor_api.py $<TARGET_FILE:fair-curves>)
  # The load test measures latencies: alone on the machine (RUN_SERIAL), so that they are its own.
  add_test(NAME editor_load COMMAND ${FAIR_EDITOR_PYTHON} ${FAIR_EDITOR_TEST_DIR}/editor_load.py $<TARGET_FILE:fair-curves>)
  set_tests_properties(editor_api PROPERTIES TIMEOUT 300 COST 10) # COST: test/CMakeLists.txt
  set_tests_properties(editor_load PROPERTIES TIMEOUT 300 RUN_SERIAL ON)
endif()

set(FAIR_EDITOR_OUT ${CMAKE_CURRENT_BINARY_DIR}/editor-test)
if(FAIR_EDITOR_NODE)
  # The page's modules in Node, no browser (test/editor/page_units.mjs).
  add_test(NAME editor_page_units COMMAND ${FAIR_EDITOR_NODE} ${FAIR_EDITOR_TEST_DIR}/page_units.mjs
           ${PROJECT_SOURCE_DIR}/tools/fair-curves/editor)
  add_test(NAME editor_browser COMMAND ${FAIR_EDITOR_NODE} ${FAIR_EDITOR_TEST_DIR}/browser_test.mjs
           $<TARGET_FILE:fair-curves> ${FAIR_EDITOR_OUT})
else()
  # No Node.js: skipped (77), or failed when the browser test is required.
  add_test(NAME editor_browser COMMAND sh -c "echo 'SKIP: no node (apt-get install nodejs npm)'; [ \"$FAIR_EDITOR_REQUIRE_BROWSER\" = 1 ] && exit 1; exit 77")
endif()
# The drag round trip is measured: alone on the machine (RUN_SERIAL).
set_tests_properties(editor_browser PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300 RUN_SERIAL ON)
