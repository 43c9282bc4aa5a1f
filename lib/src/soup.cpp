#include "geolab/soup.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace geolab {

void check_soup(const PolygonSoup& soup) {
    if (soup.offsets.empty() || soup.offsets.front() != 0 || soup.offsets.back() != soup.indices.size())
        throw std::invalid_argument("check_soup: offsets do not match indices");
    for (std::size_t v = 0; v < soup.positions.size(); ++v) {
        const auto& p = soup.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("check_soup: vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        if (vs.size() < 3)
            throw std::invalid_argument("check_soup: face " + std::to_string(f) + " has " +
                                        std::to_string(vs.size()) + " vertices (at least 3 needed)");
        for (std::size_t i = 0; i < vs.size(); ++i) {
            if (vs[i] >= soup.positions.size())
                throw std::invalid_argument("check_soup: face " + std::to_string(f) + " uses vertex " +
                                            std::to_string(vs[i]) + " but there are only " +
                                            std::to_string(soup.positions.size()));
            for (std::size_t j = 0; j < i; ++j)
                if (vs[i] == vs[j])
                    throw std::invalid_argument("check_soup: face " + std::to_string(f) + " repeats vertex " +
                                                std::to_string(vs[i]));
        }
    }
}

}  // namespace geolab
