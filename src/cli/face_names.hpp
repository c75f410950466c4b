// Face names given by a point inside each named face (--names, and the
// "names" of an edit script), turned into FaceData on a DCEL.
#pragma once

#include <string>
#include <vector>

#include "edit_script.hpp"
#include "json_out.hpp"

namespace dcel::cli {

// Names the face holding each point. InvalidInput when a point is at a
// vertex or on an edge (it names no face); `source` prefixes the message.
void name_faces(const Dcel& d, const std::vector<NamedPoint>& names, const std::string& source, FaceNames& out);

// Reads a --names file (or returns nothing for an empty path).
[[nodiscard]] std::vector<NamedPoint> load_face_names(const std::string& path);

}  // namespace dcel::cli
