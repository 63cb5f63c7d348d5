# Reads robots/bundled.json, the one list of bundled robots and their scenes, into
#   RBDC_BUNDLED_ROBOTS                  robot names, in file order
#   RBDC_BENCH_ROBOTS                    the robots the benchmarks time: these, and the big robots of
#                                        cmake/RbdcBigRobots.cmake in a benchmark build that asks for them
#   RBDC_ROBOT_<name>_URDF               absolute URDF path
#   RBDC_ROBOT_<name>_TOPOLOGY           absolute path of its topology overlay, or empty
#   RBDC_ROBOT_<name>_BASE               floating | fixed
#   RBDC_ROBOT_<name>_SCENES             scene names (the first one is benchmarked)
#   RBDC_ROBOT_<name>_VERIFIED_IN_<scene>  the scene whose verify test also checks this one, or empty
set(_rbdc_bundled_file ${PROJECT_SOURCE_DIR}/robots/bundled.json)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${_rbdc_bundled_file})
file(READ ${_rbdc_bundled_file} _rbdc_bundled_json)
string(JSON _rbdc_count LENGTH "${_rbdc_bundled_json}" robots)
set(RBDC_BUNDLED_ROBOTS "")
math(EXPR _rbdc_last "${_rbdc_count} - 1")
foreach(_i RANGE ${_rbdc_last})
  string(JSON _name GET "${_rbdc_bundled_json}" robots ${_i} name)
  string(JSON _urdf GET "${_rbdc_bundled_json}" robots ${_i} urdf)
  string(JSON _base GET "${_rbdc_bundled_json}" robots ${_i} base)
  string(JSON _topology ERROR_VARIABLE _no_topology GET "${_rbdc_bundled_json}" robots ${_i} topology)
  string(JSON _n_scenes LENGTH "${_rbdc_bundled_json}" robots ${_i} scenes)
  set(_scenes "")
  math(EXPR _last_scene "${_n_scenes} - 1")
  foreach(_k RANGE ${_last_scene})
    string(JSON _scene GET "${_rbdc_bundled_json}" robots ${_i} scenes ${_k})
    list(APPEND _scenes ${_scene})
    string(JSON _host ERROR_VARIABLE _not_hosted GET "${_rbdc_bundled_json}" robots ${_i} verified_in ${_scene})
    set(RBDC_ROBOT_${_name}_VERIFIED_IN_${_scene} "")
    if(NOT _not_hosted)
      set(RBDC_ROBOT_${_name}_VERIFIED_IN_${_scene} ${_host})
    endif()
  endforeach()
  list(APPEND RBDC_BUNDLED_ROBOTS ${_name})
  set(RBDC_ROBOT_${_name}_URDF ${PROJECT_SOURCE_DIR}/${_urdf})
  set(RBDC_ROBOT_${_name}_BASE ${_base})
  if(_no_topology)
    set(RBDC_ROBOT_${_name}_TOPOLOGY "")
  else()
    set(RBDC_ROBOT_${_name}_TOPOLOGY ${PROJECT_SOURCE_DIR}/${_topology})
  endif()
  set(RBDC_ROBOT_${_name}_SCENES ${_scenes})
endforeach()
set(RBDC_BENCH_ROBOTS ${RBDC_BUNDLED_ROBOTS})
