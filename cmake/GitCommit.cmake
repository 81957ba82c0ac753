# Writes OUTPUT, a source file defining signorini::gitCommit(), from `git describe --always
# --dirty` of SOURCE_DIR ("unknown" outside a git checkout). Run at every build; the file is
# rewritten only when the commit changed, so an unchanged tree recompiles nothing.
execute_process(COMMAND git describe --always --dirty WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT commit)
  set(commit unknown)
endif()
set(text "// Generated at build time by cmake/GitCommit.cmake.\n#include \"signorini/core/Version.hpp\"\n\nconst char* signorini::gitCommit() { return \"${commit}\"; }\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUTPUT} "${text}")
endif()
