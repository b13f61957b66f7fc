// The exercises the registry holds: every one of examples/exercises/list.h, in its order; or, in a
// browser page's module (web/CMakeLists.txt builds this file with PENUMBRA_PAGE=name for each
// page), that page's exercise alone, so that the page links no other exercise's code.
#include "exercise_list.h"
#include "exercises/list.h"

namespace penumbra::examples {

namespace exercises {
#define PENUMBRA_DECLARE(name) Exercise name();
PENUMBRA_EXERCISES(PENUMBRA_DECLARE)
#undef PENUMBRA_DECLARE
}  // namespace exercises

std::vector<Exercise> exercise_registry() {
#ifdef PENUMBRA_PAGE
    return {exercises::PENUMBRA_PAGE()};
#else
    return {
#define PENUMBRA_ITEM(name) exercises::name(),
        PENUMBRA_EXERCISES(PENUMBRA_ITEM)
#undef PENUMBRA_ITEM
    };
#endif
}

}  // namespace penumbra::examples
