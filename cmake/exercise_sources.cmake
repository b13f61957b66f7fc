# The course exercises' sources shared by the desktop app (examples/), the web module (web/) and the
# query fuzz target (tests/fuzz/): one list, so a file split out of them reaches all three.
set(PENUMBRA_EXERCISE_SOURCES
    ${CMAKE_SOURCE_DIR}/examples/exercises.cpp
    ${CMAKE_SOURCE_DIR}/examples/exercise_keys.cpp
    ${CMAKE_SOURCE_DIR}/examples/fly_camera.cpp
    ${CMAKE_SOURCE_DIR}/examples/exercise_list.cpp)
