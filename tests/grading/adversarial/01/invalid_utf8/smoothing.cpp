// ADVERSARIAL CASE invalid_utf8: a stub whose output holds bytes that are not UTF-8 (an honest bug can print them):
// results.json must stay valid, with the bytes replaced.
#include <iostream>

#include "geolab/halfedge.hpp"

namespace geolab::halfedge {

void laplacian_smoothing(Mesh&, double, int) {
    std::cout << "stray bytes: \xff\xfe \xc3\x28 \xed\xa0\x80 end" << std::endl;
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfedge
