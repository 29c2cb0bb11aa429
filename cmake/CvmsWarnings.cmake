# Warnings for our own targets only: consumers never inherit them.
function(cvms_set_warnings target)
  if(MSVC)
    target_compile_options(${target} PRIVATE /W4 $<$<BOOL:${CVMS_WARNINGS_AS_ERRORS}>:/WX>)
  else()
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic
      $<$<BOOL:${CVMS_WARNINGS_AS_ERRORS}>:-Werror>)
  endif()
endfunction()
