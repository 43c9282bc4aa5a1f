#include "geolab/grading/chain.hpp"
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
std::map<std::string, std::string>& builds_on_tests() {
    static std::map<std::string, std::string> tasks;
    return tasks;
}
std::vector<std::string>& attached_figures() {
    static std::vector<std::string> figures;
    return figures;
}
}  // namespace detail

}  // namespace geolab
