# momenta_as_literal(TEXT OUT): TEXT as C++ raw string literals, cut into pieces the compiler
# concatenates (each well under the 64 KiB a single literal may portably hold). Fails when the
# text holds the literals' delimiter. For the build's scripts that embed files in the library
# (EmbedReportBundle.cmake; the engine's, embed_engine.mjs, cuts its literals the same way).
function(momenta_as_literal text out)
  set(delimiter "momenta_bundle")
  string(FIND "${text}" ")${delimiter}\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "the embedded text holds the literal's delimiter")
  endif()
  string(LENGTH "${text}" length)
  set(pieces "")
  set(at 0)
  while(at LESS length)
    string(SUBSTRING "${text}" ${at} 30000 piece)
    string(APPEND pieces "R\"${delimiter}(${piece})${delimiter}\"\n")
    math(EXPR at "${at} + 30000")
  endwhile()
  if(pieces STREQUAL "")
    set(pieces "\"\"")
  endif()
  set(${out} "${pieces}" PARENT_SCOPE)
endfunction()
