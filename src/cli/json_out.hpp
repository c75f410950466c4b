// JSON output shared by the query and edit commands: points, locations,
// stabbing pieces and face names, each on one line.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/io/json_string.hpp"
#include "dcel/locate.hpp"
#include "dcel/stab.hpp"
#include "dcel/user_data.hpp"

namespace dcel::cli {

// Face names for the output; an empty name is written as null.
using FaceNames = FaceData<std::string>;

using io::json_string;                                                  // quoted and escaped
[[nodiscard]] std::string json_point(Point p);                          // [x, y], shortest round trip
[[nodiscard]] std::string json_name(const FaceNames* names, FaceId f);  // "West" or null

// The members after "point": "face": f | "edge": e, "faces": [left of 2e, left of 2e+1] |
// "vertex": v, each face followed by its name when names are given.
[[nodiscard]] std::string json_location_members(const Dcel& d, const Location& l, const FaceNames* names);

// "faces": [...] (and "names": [...]), "pieces": [{"face": f}, {"edge": e}, {"edge": e, "along": true}, {"vertex": v}]
[[nodiscard]] std::string json_stab_members(const std::vector<StabPiece>& pieces, const FaceNames* names);

}  // namespace dcel::cli
