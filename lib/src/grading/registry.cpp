#include "geolab/grading/test.hpp"

namespace geolab {

std::map<std::string, TestMeta>& test_registry() {
    static std::map<std::string, TestMeta> registry;
    return registry;
}

namespace detail {
TestMeta& meta_for(const doctest::detail::TestCase& tc) { return test_registry()[tc.m_name]; }
std::string& current_test() {
    static std::string name;
    return name;
}
std::vector<std::string>& attached_figures() {
    static std::vector<std::string> figures;
    return figures;
}
}  // namespace detail

}  // namespace geolab
