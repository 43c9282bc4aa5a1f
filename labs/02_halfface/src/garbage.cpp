// Task 3: deletion and garbage collection (handout §5).
#include <algorithm>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

void delete_cell(Mesh& mesh, Cell c) {
    throw geolab::NotImplemented(__func__);
}

void delete_vertex(Mesh& mesh, Vertex v) {
    throw geolab::NotImplemented(__func__);
}

Remap garbage_collection(Mesh& mesh) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfface
