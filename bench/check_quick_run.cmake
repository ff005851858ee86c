# CTest "bench: quick run writes its tables": runs `animator-bench --quick --runs 1 --out OUT` and
# checks that every CSV has its columns and that every number in it is finite. Timings are never
# checked. cmake -DBENCH=... -DOUT=... -P check_quick_run.cmake
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${BENCH} --quick --runs 1 --out ${OUT} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "animator-bench --quick failed (${rc}):\n${out}\n${err}")
endif()

# file | columns | the columns that hold numbers
set(tables
  "exact.csv|scene,measure,backend,step,error,ms,runs,events|step,error,ms,runs,events"
  "exact_ratio.csv|scene,measure,custom_error,custom_ms,bullet_reaches,bullet_ms_at_custom_error,ratio,bullet_best_error,bullet_best_step,bullet_best_ms|custom_error,custom_ms,bullet_reaches,bullet_ms_at_custom_error,ratio,bullet_best_error,bullet_best_step,bullet_best_ms"
  "exact_passes.csv|backend,step,ccd,speeds,passes|step,ccd,speeds,passes"
  "rest.csv|scene,measure,backend,step,error,ms,runs|step,error,ms,runs"
  "gas.csv|backend,n,step,sim_seconds,wall_s,wall_per_sim_s,runs,collisions,collisions_per_s,energy_error,overlap,peak_rss_mb,baseline_rss_mb,pair_tests_done,pair_tests_skipped|n,step,sim_seconds,wall_s,wall_per_sim_s,runs,collisions,collisions_per_s,energy_error,overlap,peak_rss_mb,baseline_rss_mb,pair_tests_done,pair_tests_skipped"
  "gas_fit.csv|backend,exponent,points|exponent,points"
  "gas_ratio.csv|n,custom_collisions_per_s,reference_collisions_per_s,ratio|n,custom_collisions_per_s,reference_collisions_per_s,ratio"
  "mesh.csv|case,query,triangles_a,triangles_b,bvh_us,brute_us,speedup,bvh_feature_tests,brute_feature_tests,bvh_node_pairs,contact,time_difference,normal_difference,point_difference|query,triangles_a,triangles_b,bvh_us,brute_us,speedup,bvh_feature_tests,brute_feature_tests,bvh_node_pairs,contact,time_difference,normal_difference,point_difference"
  "long.csv|backend,step,seconds,wall_s,runs,peak_rss_mb,baseline_rss_mb,collisions,segments,energy_error,position_error_m|step,seconds,wall_s,runs,peak_rss_mb,baseline_rss_mb,collisions,segments,energy_error,position_error_m"
  "skip.csv|what,example,value,of,note|value,of")

set(number "^-?[0-9]+(\\.[0-9]*)?([eE][-+]?[0-9]+)?$")
foreach(table IN LISTS tables)
  string(REPLACE "|" ";" parts "${table}")
  list(GET parts 0 name)
  list(GET parts 1 header)
  list(GET parts 2 numeric)
  string(REPLACE "," ";" columns "${header}")
  string(REPLACE "," ";" numeric "${numeric}")
  list(LENGTH columns width)
  if(NOT EXISTS ${OUT}/${name})
    message(FATAL_ERROR "${name} was not written")
  endif()
  file(STRINGS ${OUT}/${name} lines)
  list(LENGTH lines count)
  if(count LESS 2)
    message(FATAL_ERROR "${name} has no rows")
  endif()
  list(GET lines 0 first)
  if(NOT first STREQUAL header)
    message(FATAL_ERROR "${name}: columns '${first}', expected '${header}'")
  endif()
  list(REMOVE_AT lines 0)
  foreach(line IN LISTS lines)
    # Quoted text fields hold commas: drop them first (they are not numbers).
    string(REGEX REPLACE "\"[^\"]*\"" "text" line "${line}")
    string(REPLACE ";" "_" line "${line}")
    string(REPLACE "," ";" fields "${line}")
    list(LENGTH fields n)
    if(NOT n EQUAL width)
      message(FATAL_ERROR "${name}: ${n} fields, expected ${width}: ${line}")
    endif()
    foreach(column IN LISTS numeric)
      list(FIND columns ${column} index)
      list(GET fields ${index} value)
      if(NOT value MATCHES "${number}")
        message(FATAL_ERROR "${name}: ${column} is '${value}', not a finite number: ${line}")
      endif()
    endforeach()
  endforeach()
  message(STATUS "${name}: ${count} lines, every number finite")
endforeach()
