#include "geolab/soup.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace geolab {

void check_soup(const PolygonSoup& soup) {
    if (soup.offsets.empty() || soup.offsets.front() != 0 || soup.offsets.back() != soup.indices.size())
        throw std::invalid_argument("check_soup: offsets do not match indices");
    for (std::size_t v = 0; v < soup.positions.size(); ++v) {
        const auto& p = soup.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("check_soup: vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
    // Repeats: faces are short, so compare pairs; a long face (more than `short_face` vertices) stamps its
    // vertices in `seen_in` instead, so a face of n vertices costs O(n), never O(n²).
    constexpr std::size_t short_face = 16;
    std::vector<std::size_t> seen_in;  // seen_in[v] = 1 + the last long face that used v; sized on first need
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        if (vs.size() < 3)
            throw std::invalid_argument("check_soup: face " + std::to_string(f) + " has " +
                                        std::to_string(vs.size()) + " vertices (at least 3 needed)");
        const bool is_long = vs.size() > short_face;
        if (is_long && seen_in.empty()) seen_in.assign(soup.positions.size(), 0);
        for (std::size_t i = 0; i < vs.size(); ++i) {
            if (vs[i] >= soup.positions.size())
                throw std::invalid_argument("check_soup: face " + std::to_string(f) + " uses vertex " +
                                            std::to_string(vs[i]) + " but there are only " +
                                            std::to_string(soup.positions.size()));
            bool repeated = false;
            if (is_long)
                repeated = std::exchange(seen_in[vs[i]], f + 1) == f + 1;
            else
                for (std::size_t j = 0; j < i && !repeated; ++j) repeated = vs[i] == vs[j];
            if (repeated)
                throw std::invalid_argument("check_soup: face " + std::to_string(f) + " repeats vertex " +
                                            std::to_string(vs[i]));
        }
    }
}

}  // namespace geolab
