# -DPLUMBAGO_SANITIZE=ON: every target built with clang's AddressSanitizer and
# UndefinedBehaviorSanitizer (any UB report stops the program), and instrumented for
# libFuzzer, so that the fuzz targets in fuzz/ link against the same library.
# plumbago_tests then holds only the tests that need no GL context and no command line
# program (plumbago_non_gl_tests below). scripts/sanitize.sh builds and runs them.

if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "PLUMBAGO_SANITIZE needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++-14")
endif()
add_compile_options(-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=undefined
                    -fno-omit-frame-pointer -gline-tables-only)
add_link_options(-fsanitize=address,undefined)

# Keeps in `sources_var` the test sources that include no GPU or parity header, use no
# GL fixture and do not run the plumbago program: they link without the GPU backend.
function(plumbago_non_gl_tests sources_var)
  set(kept "")
  foreach(source IN LISTS ${sources_var})
    file(STRINGS "${source}" needs_gl
         REGEX "#include \"(gpu|parity)/|#include \"tests/support/(parity_checks|cli_run)\\.hpp\"|GlTest|PLUMBAGO_CLI")
    if(NOT needs_gl)
      list(APPEND kept "${source}")
    endif()
    # A test that starts to need GL moves out of the selection at the next build.
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${source}")
  endforeach()
  set(${sources_var} "${kept}" PARENT_SCOPE)
endfunction()
