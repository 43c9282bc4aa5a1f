#include "geolab/grading/test.hpp"

namespace geolab {

std::map<std::string, TestMeta>& test_registry() {
    static std::map<std::string, TestMeta> registry;
    return registry;
}

namespace detail {
TestMeta& meta_for(const doctest::detail::TestCase& tc) { return test_registry()[tc.m_name]; }
}  // namespace detail

}  // namespace geolab
