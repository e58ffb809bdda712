# ctest: runs the Khronos glTF validator (tools/gltf-validator/validate.mjs) over the given scenes.
# Inputs: NODE (path or NOTFOUND), VALIDATOR_DIR, SCENES ('|'-separated). Fails, never skips, when
# the tools are missing: CI must not pass without validating.
if(NOT NODE OR NODE MATCHES "NOTFOUND$")
  message(FATAL_ERROR "gltf validator: node (Node.js) was not found when configuring; run scripts/bootstrap, then reconfigure")
endif()
if(NOT EXISTS "${VALIDATOR_DIR}/node_modules/gltf-validator/package.json")
  message(FATAL_ERROR "gltf validator: ${VALIDATOR_DIR}/node_modules is missing; run scripts/bootstrap")
endif()
string(REPLACE "|" ";" scenes "${SCENES}")
list(LENGTH scenes count)
if(count EQUAL 0)
  message(FATAL_ERROR "gltf validator: no scenes given (content/scenes is empty?)")
endif()
execute_process(COMMAND "${NODE}" "${VALIDATOR_DIR}/validate.mjs" ${scenes} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "gltf validator: errors in the scenes above (exit ${result})")
endif()
message(STATUS "gltf validator: ${count} scenes without errors")
