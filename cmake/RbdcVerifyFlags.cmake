# Writes rbdc-verify.json into the build dir: the compiler, the external include dirs and the
# libraries that `rbdc verify` needs to compile its harness against the static runtime library.
# The libraries are read from rbdc_runtime's own link list, so they follow the runtime's needs.
# The runtime's include dir and library file come from the source tree or install layout.
get_target_property(_rbdc_runtime_links rbdc_runtime LINK_LIBRARIES)
set(_rbdc_verify_libraries "")
foreach(_lib IN LISTS _rbdc_runtime_links)
  if(TARGET ${_lib})
    get_target_property(_type ${_lib} TYPE)
    if(NOT _type STREQUAL "INTERFACE_LIBRARY")
      list(APPEND _rbdc_verify_libraries "\"$<TARGET_FILE:${_lib}>\"")
    endif()
  else()
    list(APPEND _rbdc_verify_libraries "\"-l${_lib}\"")
  endif()
endforeach()
list(JOIN _rbdc_verify_libraries ", " _rbdc_verify_libraries)
set(_rbdc_eigen_includes "$<TARGET_PROPERTY:Eigen3::Eigen,INTERFACE_INCLUDE_DIRECTORIES>")
file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/rbdc-verify.json CONTENT "{
  \"cxx\": \"${CMAKE_CXX_COMPILER}\",
  \"include_dirs\": [\"$<JOIN:${_rbdc_eigen_includes},\", \">\"],
  \"libraries\": [${_rbdc_verify_libraries}]
}
")
