# Comments, test texts and scripts cite only what a reader of the repository
# can follow: an ISG functional description by its name and section
# (FCT-S1 §2.8.2, FCT-C2 §2.7, spindle_link seed ...), a TF5200 page or
# parameter (P-CHAN-00052, TF5200 #CS), or a file in docs/. This check
# fails, listing file:line, on a citation of a working document that is not
# in the repository (the product spec, the syntax and parameter notes, the
# upper-case architecture notes, anything in the shared folder beside the
# repository).
#
#   cmake -DNCK_SOURCE_DIR=<repo> -P tests/doc_citations.cmake
#
# The patterns are put together from pieces so that this file does not
# match them itself.
if(NOT NCK_SOURCE_DIR)
  get_filename_component(NCK_SOURCE_DIR "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
endif()

set(spec "SP")
string(APPEND spec "EC")
set(facts "act")
set(upper_facts "FA")
string(APPEND upper_facts "CTS")
set(arch "ARCHI")
string(APPEND arch "TECTURE")
set(shared "shar")
string(APPEND shared "ed/")
set(patterns
    "${spec} ?(§|[0-9])"                  # "<spec> 3.3", "<spec> §2.3"
    "${spec} [Ee]rrat"                    # "<spec> erratum"
    "${spec}\\.md"
    "[Ss]eed [Ee]rrat"                    # the spec's mark for a seed mistake
    "[Ff]${facts}s? sheet"                # the fact-sheet, by name
    "[Ff]${facts}s [A-F]([0-9]|[^a-z]|$)" # a fact-sheet section: B6, A1-A6, D
    "[(,;] ?[Ff]${facts}s(\n|$)"         # the same, its section on the next line
    "PARAMETER_${upper_facts}"
    "ISG_SYNTAX_${upper_facts}"
    "${arch}\\.md"                        # docs/architecture.md (lower case) is fine
    "\\.\\./${shared}")
string(JOIN "|" any_pattern ${patterns})

set(globs)
foreach(dir src include apps python tests bench fuzz scripts web examples cmake)
  foreach(ext cpp hpp h def py pyi js mjs sh cmake html md json nc lis plc)
    list(APPEND globs "${NCK_SOURCE_DIR}/${dir}/*.${ext}")
  endforeach()
  list(APPEND globs "${NCK_SOURCE_DIR}/${dir}/CMakeLists.txt")
endforeach()
file(GLOB_RECURSE files LIST_DIRECTORIES false ${globs})
list(APPEND files "${NCK_SOURCE_DIR}/CMakeLists.txt")
list(FILTER files EXCLUDE REGEX "/node_modules/")
list(REMOVE_DUPLICATES files)
list(SORT files)

set(found 0)
foreach(f IN LISTS files)
  file(READ "${f}" text)
  string(REGEX MATCH "${any_pattern}" hit "${text}")
  if(NOT hit)
    continue()
  endif()
  # One list element per line: characters that CMake's lists treat
  # specially (; [ ] \) are replaced first, so lines are neither split nor
  # joined.
  string(REPLACE "\\" "/" text "${text}")
  string(REPLACE ";" "," text "${text}")
  string(REPLACE "[" "(" text "${text}")
  string(REPLACE "]" ")" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  file(RELATIVE_PATH rel "${NCK_SOURCE_DIR}" "${f}")
  set(n 0)
  foreach(line IN LISTS lines)
    math(EXPR n "${n} + 1")
    string(REGEX MATCH "${any_pattern}" hit "${line}")
    if(hit)
      string(STRIP "${line}" shown)
      message("${rel}:${n}: cites a document outside the repository (\"${hit}\"): ${shown}")
      math(EXPR found "${found} + 1")
    endif()
  endforeach()
endforeach()

list(LENGTH files checked)
if(found GREATER 0)
  message(FATAL_ERROR "${found} line(s) cite a document that is not in the repository; cite the seed "
                      "section, the TF5200 page or parameter, or a file in docs/ instead")
endif()
message(STATUS "doc_citations: ${checked} files, no citation of a document outside the repository")
