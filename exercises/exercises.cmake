# Graded exercises (exercises/NN-slug/): built and run by `t2 check` / `t2 grade`, not by CMake.
# The grader's own tests run the t2 tool, which links student code against this build's libt2_kernel.a (the kernel target).
foreach(t test_grader test_grader_release test_exercises test_exercises_07c test_exercises_09c test_exercises_10c)
  if(TARGET ${t})
    add_dependencies(${t} t2_tool t2)
  endif()
endforeach()
