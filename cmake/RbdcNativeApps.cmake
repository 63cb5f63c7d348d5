# rbdc_native_apps(): compiles the calling directory's targets with -march=native when
# RBDC_NATIVE_APPS is ON (the default). For the simulator, the controllers and the MuJoCo
# comparison: they are not installed, so they run on the machine that builds them, and FMA/AVX make
# the generated dynamics they call about twice as fast (docs/performance.md, "Native by default
# where it runs"). The installed runtime and rbdc_generate() stay portable unless RBDC_NATIVE.
function(rbdc_native_apps)
  if(RBDC_NATIVE_APPS AND NOT RBDC_NATIVE)  # RBDC_NATIVE already applies it everywhere
    add_compile_options(-march=native)
  endif()
endfunction()
