# The include rule: dependencies run one way, core <- engine <- nodes <- graph <- runner.
#
#   core/              includes core/ only
#   engine/<module>/   core/ and engine/ (the method knows nothing of stages or the graph)
#   nodes/<stage>/     core/, engine/ and its own stage, never another stage; the node adapters
#                      (*_node.cpp, *_node.h) also graph/
#   graph/             core/, graph/ and the engine's interface, engine/refine/refine.h
#   runner/            anything but nodes/ (it sees the stages through the graph's registry)
#
# Fails the build, naming every include that breaks the rule. Run by the build (top-level
# CMakeLists.txt) before anything compiles:
#   cmake -DROOT=<source dir> -DSTAMP=<file written on success> -P check_includes.cmake
cmake_minimum_required(VERSION 3.22)

set(kEngineInterface "engine/refine/refine.h")

# Sets `verdict` to "" when `source` (relative to ROOT) may include the project header
# `target` (as written between the quotes), else to the reason it may not.
function(include_verdict source target verdict)
  string(REGEX MATCH "^[^/]+" target_root "${target}")
  string(REGEX MATCH "^[^/]+" source_root "${source}")
  set(reason "")
  if(source_root STREQUAL "core")
    if(NOT target_root STREQUAL "core")
      set(reason "core/ includes core/ only")
    endif()
  elseif(source_root STREQUAL "engine")
    if(NOT target_root MATCHES "^(core|engine)$")
      set(reason "engine/ includes core/ and engine/ only")
    endif()
  elseif(source_root STREQUAL "nodes")
    string(REGEX MATCH "^nodes/([^/]+)/" unused "${source}")
    set(stage ${CMAKE_MATCH_1})
    get_filename_component(name "${source}" NAME)
    if(target_root STREQUAL "graph")
      if(NOT name MATCHES "_node\\.(cpp|h)$")
        set(reason "a stage's algorithms know nothing of the graph; only *_node.cpp/.h adapters include graph/")
      endif()
    elseif(target_root STREQUAL "nodes")
      if(NOT target MATCHES "^nodes/${stage}/")
        set(reason "a stage uses core/ and engine/, never another stage")
      endif()
    elseif(NOT target_root MATCHES "^(core|engine)$")
      set(reason "a stage includes core/, engine/, its own stage and (adapters) graph/ only")
    endif()
  elseif(source_root STREQUAL "graph")
    if(target_root STREQUAL "engine")
      if(NOT target STREQUAL kEngineInterface)
        set(reason "graph/ uses the engine through ${kEngineInterface} only")
      endif()
    elseif(NOT target_root MATCHES "^(core|graph)$")
      set(reason "graph/ includes core/, graph/ and ${kEngineInterface} only")
    endif()
  elseif(source_root STREQUAL "runner")
    if(target_root STREQUAL "nodes")
      set(reason "runner/ uses the stages through the graph, never their headers")
    endif()
  endif()
  set(${verdict} "${reason}" PARENT_SCOPE)
endfunction()

set(problems "")
set(checked 0)
foreach(layer core engine nodes graph runner)
  file(GLOB_RECURSE sources RELATIVE ${ROOT} ${ROOT}/${layer}/*.h ${ROOT}/${layer}/*.cpp)
  foreach(source ${sources})
    math(EXPR checked "${checked} + 1")
    file(STRINGS ${ROOT}/${source} includes
         REGEX "^[ \t]*#[ \t]*include[ \t]+\"(core|engine|nodes|graph|runner)/")
    foreach(line ${includes})
      string(REGEX MATCH "\"([^\"]+)\"" unused "${line}")
      include_verdict("${source}" "${CMAKE_MATCH_1}" reason)
      if(reason)
        string(APPEND problems "\n  ${source}: #include \"${CMAKE_MATCH_1}\" (${reason})")
      endif()
    endforeach()
  endforeach()
endforeach()
if(problems)
  message(FATAL_ERROR "includes that break the include rule (cmake/check_includes.cmake):${problems}")
endif()
file(WRITE ${STAMP} "${checked} files follow the include rule\n")
