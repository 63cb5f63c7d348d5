# rbdc_generate() inside the rbdc build itself: the launcher and generator come from the source tree
# and rbdc-model from this build (see RbdcGenerate.cmake).
set(RBDC_LAUNCHER ${PROJECT_SOURCE_DIR}/rbdc)
set(RBDC_SHARE_DIR ${PROJECT_SOURCE_DIR})
include(${CMAKE_CURRENT_LIST_DIR}/RbdcGenerate.cmake)
