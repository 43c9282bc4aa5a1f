// geolab info MESH: placeholder until lab 01's API lands.
#include "commands.hpp"
namespace geolab::cli {
void add_info(CLI::App&, int&) {}
}
