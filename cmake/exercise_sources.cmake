# The course exercises' sources shared by the desktop app (examples/), the web module (web/) and the
# query fuzz target (tests/fuzz/): one list, so a file split out of them reaches all three. The
# exercises themselves are examples/exercises/*.cpp, one module each (listed in
# examples/exercises/list.h: PENUMBRA_EXERCISE_NAMES is read from there).
file(GLOB PENUMBRA_EXERCISE_MODULES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/examples/exercises/*.cpp)
# The registry and the modules (what penumbra_catalog needs: no renderer, no GL).
set(PENUMBRA_EXERCISE_LIST_SOURCES ${CMAKE_SOURCE_DIR}/examples/exercise_list.cpp ${CMAKE_SOURCE_DIR}/examples/exercise_registry.cpp
    ${CMAKE_SOURCE_DIR}/examples/fly_camera.cpp ${PENUMBRA_EXERCISE_MODULES})
set(PENUMBRA_EXERCISE_SOURCES
    ${CMAKE_SOURCE_DIR}/examples/exercises.cpp
    ${CMAKE_SOURCE_DIR}/examples/exercise_budget.cpp
    ${CMAKE_SOURCE_DIR}/examples/exercise_keys.cpp
    ${CMAKE_SOURCE_DIR}/examples/exercise_scenes.cpp
    ${CMAKE_SOURCE_DIR}/examples/frame_timing.cpp
    ${PENUMBRA_EXERCISE_LIST_SOURCES})
# The exercises' names in the list's order (X(name) lines): the desktop tests' list.
file(READ ${CMAKE_SOURCE_DIR}/examples/exercises/list.h PENUMBRA_EXERCISE_LIST_TEXT)
string(REGEX MATCHALL "\n *X\\([a-z0-9_]+\\)" PENUMBRA_EXERCISE_LINES "${PENUMBRA_EXERCISE_LIST_TEXT}")
set(PENUMBRA_EXERCISE_NAMES)
foreach(line ${PENUMBRA_EXERCISE_LINES})
  string(REGEX REPLACE "^\n *X\\(([a-z0-9_]+)\\)$" "\\1" name "${line}")
  list(APPEND PENUMBRA_EXERCISE_NAMES ${name})
endforeach()
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/examples/exercises/list.h)
