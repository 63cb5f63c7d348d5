# rbdc_generate(TARGET name URDF file [SCENE file] [TOPOLOGY file] [NAME robot]
#               [FIXED_BASE | FLOATING_BASE] [LOCK_MIMIC | INDEPENDENT_MIMIC])
#
# Generates the robot's C++ headers at build time into ${CMAKE_CURRENT_BINARY_DIR}/rbdc/<name> and
# creates the INTERFACE target `name` whose include root is that directory (portable code unless the
# project sets RBDC_NATIVE=ON, which adds -march=native for whoever links it; docs/performance.md,
# "Compiler contract"):
#   #include "<robot>/<scene>.hpp"   // namespace rbdc_gen::<robot>::<scene>, docs/generated_api.md
# They are regenerated when the URDF, scene, topology, templates or generator sources change.
# Needs RBDC_LAUNCHER (the `rbdc` command) and RBDC_SHARE_DIR, both set by find_package(rbdc), or
# inside the rbdc build itself by cmake/RbdcInTree.cmake. With an installed rbdc the headers are
# listed at configure time (rbdc generate --list-outputs); in-tree rbdc-model is not built yet at
# configure time, so the generation runs after it and only the stamp file is a declared output.
function(rbdc_generate)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "FIXED_BASE;FLOATING_BASE;LOCK_MIMIC;INDEPENDENT_MIMIC" "TARGET;URDF;SCENE;TOPOLOGY;NAME" "")
  if(NOT ARG_TARGET OR NOT ARG_URDF)
    message(FATAL_ERROR "rbdc_generate: TARGET and URDF are required")
  endif()
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "rbdc_generate: unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT RBDC_LAUNCHER)
    message(FATAL_ERROR "rbdc_generate: RBDC_LAUNCHER is not set (use find_package(rbdc))")
  endif()
  set(inputs "")
  foreach(file_argument URDF SCENE TOPOLOGY)
    if(ARG_${file_argument})
      get_filename_component(ARG_${file_argument} "${ARG_${file_argument}}" ABSOLUTE)
      list(APPEND inputs "${ARG_${file_argument}}")
    endif()
  endforeach()
  set(out "${CMAKE_CURRENT_BINARY_DIR}/rbdc/${ARG_TARGET}")
  set(arguments "${ARG_URDF}" -o "${out}")
  if(ARG_SCENE)
    list(APPEND arguments --scene "${ARG_SCENE}")
  endif()
  if(ARG_TOPOLOGY)
    list(APPEND arguments --topology "${ARG_TOPOLOGY}")
  endif()
  if(ARG_NAME)
    list(APPEND arguments --name "${ARG_NAME}")
  endif()
  if(ARG_FIXED_BASE)
    list(APPEND arguments --fixed-base)
  elseif(ARG_FLOATING_BASE)
    list(APPEND arguments --floating-base)
  endif()
  if(ARG_LOCK_MIMIC)
    list(APPEND arguments --lock-mimic)
  elseif(ARG_INDEPENDENT_MIMIC)
    list(APPEND arguments --independent-mimic)
  endif()

  set(launcher "${RBDC_LAUNCHER}")
  set(tool_dependency "")
  set(outputs "")
  if(TARGET rbdc-model)
    set(launcher "${CMAKE_COMMAND}" -E env "RBDC_MODEL_TOOL=$<TARGET_FILE:rbdc-model>" "${RBDC_LAUNCHER}")
    set(tool_dependency rbdc-model)
  else()
    execute_process(COMMAND "${RBDC_LAUNCHER}" generate ${arguments} --list-outputs
                    OUTPUT_VARIABLE outputs ERROR_VARIABLE errors RESULT_VARIABLE result
                    OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT result EQUAL 0)
      message(FATAL_ERROR "rbdc_generate(${ARG_TARGET}): ${errors}")
    endif()
    string(REPLACE "\n" ";" outputs "${outputs}")
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${inputs})
  endif()

  file(GLOB_RECURSE generator_sources "${RBDC_SHARE_DIR}/generator/rbdcgen/*.py" "${RBDC_SHARE_DIR}/templates/*.j2")
  set(stamp "${out}.stamp")
  # Unchanged headers are not rewritten, so a stamp records the run and the headers are byproducts.
  add_custom_command(OUTPUT "${stamp}" BYPRODUCTS ${outputs}
                     COMMAND ${launcher} generate ${arguments}
                     COMMAND "${CMAKE_COMMAND}" -E touch "${stamp}"
                     DEPENDS ${inputs} ${generator_sources} ${tool_dependency}
                     COMMENT "rbdc: generating ${ARG_TARGET} from ${ARG_URDF}" VERBATIM)
  add_custom_target(${ARG_TARGET}_generate DEPENDS "${stamp}")
  add_library(${ARG_TARGET} INTERFACE)
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_generate)
  target_include_directories(${ARG_TARGET} INTERFACE "${out}")
  target_link_libraries(${ARG_TARGET} INTERFACE Eigen3::Eigen)
  target_compile_features(${ARG_TARGET} INTERFACE cxx_std_17)
  # FMA and AVX halve the generated code's instructions; rbdc's own build applies RBDC_NATIVE globally.
  if(RBDC_NATIVE AND NOT CMAKE_PROJECT_NAME STREQUAL "rbdc")
    target_compile_options(${ARG_TARGET} INTERFACE $<$<COMPILE_LANGUAGE:CXX>:-march=native>)
  endif()
endfunction()
