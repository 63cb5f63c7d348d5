# The robot corpus: public robot URDFs kept out of the repository (their licences differ from ours),
# by default ../shared/robots beside the clone when it exists. The conformance tests read it, and the
# benchmarks' big robots (Talos, cmake/RbdcBigRobots.cmake). Empty or missing: the conformance tests
# are reported as not run (docs/model.md, "Conformance corpus") and the corpus robots are skipped.
set(_rbdc_default_corpus "")
if(IS_DIRECTORY ${PROJECT_SOURCE_DIR}/../shared/robots)
  get_filename_component(_rbdc_default_corpus ${PROJECT_SOURCE_DIR}/../shared/robots ABSOLUTE)
endif()
set(RBDC_ROBOT_CORPUS "${_rbdc_default_corpus}" CACHE PATH "Folder of public robot URDFs (conformance tests, big-robot benchmarks)")
