// ADVERSARIAL CASE tmp_2_use: a stub that #includes what tmp_1_plant left in /tmp, /var/tmp or /dev/shm.
#if __has_include("/tmp/geolab_adv_planted.cpp")
#include "/tmp/geolab_adv_planted.cpp"
#elif __has_include("/var/tmp/geolab_adv_planted.cpp")
#include "/var/tmp/geolab_adv_planted.cpp"
#elif __has_include("/dev/shm/geolab_adv_planted.cpp")
#include "/dev/shm/geolab_adv_planted.cpp"
#else
#include "geolab/halfedge.hpp"

namespace geolab::halfedge {

void laplacian_smoothing(Mesh&, double, int) { throw geolab::NotImplemented(__func__); }

}  // namespace geolab::halfedge
#endif
