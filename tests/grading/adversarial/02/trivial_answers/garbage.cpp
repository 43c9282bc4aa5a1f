// ADVERSARIAL CASE trivial_answers: every function of lab 02 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 3: deletion and garbage collection (handout §5).
#include <algorithm>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

void delete_cell(Mesh& mesh, Cell c) {
    return;
}

void delete_vertex(Mesh& mesh, Vertex v) {
    return;
}

Remap garbage_collection(Mesh& mesh) {
    return {};
}

}  // namespace geolab::halfface
