// ADVERSARIAL CASE always_throws: every function of lab 02 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 3: deletion and garbage collection (handout §5).
#include <algorithm>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

void delete_cell(Mesh& mesh, Cell c) {
    throw std::invalid_argument(__func__);
}

void delete_vertex(Mesh& mesh, Vertex v) {
    throw std::invalid_argument(__func__);
}

Remap garbage_collection(Mesh& mesh) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::halfface
