// The list of exercises, one line each, in the order of the pages' index and the desktop's keys
// (1-8, Tab). X(name) names the module examples/exercises/name.cpp and its function
// exercises::name(). exercise_registry.cpp reads the list; so do cmake/exercise_sources.cmake (a
// desktop.NAME test each) and tests/web/harness.mjs (PAGES). Adding an exercise: its file and its
// line here (one line, above the end).
#pragma once

#define PENUMBRA_EXERCISES(X) \
    X(w09p1)                  \
    X(w09p2a)                 \
    X(w09p2b)                 \
    X(w09p2c)                 \
    X(volumes)                \
    X(soft)                   \
    X(stencil)                \
    X(multipass)              \
    X(cascades)               \
    X(bulb)                   \
    /* the end of the list: a new line goes above */
