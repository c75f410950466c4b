// Face names given by a point inside each named face (--names, and the
// "names" of an edit script), turned into FaceData on a DCEL.
#pragma once

#include <string>
#include <vector>

#include "edit_script.hpp"
#include "json_out.hpp"

namespace dcel::cli {

// Names the face holding each point and returns those faces, in the order
// of `names`. InvalidInput when a point is at a vertex or on an edge (it
// names no face); `source` prefixes the message. O((V + E) log(V + E) + k
// log(V + E)) expected for k names: the points are located with a
// PointLocator once there are more than a few of them.
std::vector<FaceId> name_faces(const Dcel& d, const std::vector<NamedPoint>& names, const std::string& source,
                               FaceNames& out);

// Reads a --names file (or returns nothing for an empty path).
[[nodiscard]] std::vector<NamedPoint> load_face_names(const std::string& path);

}  // namespace dcel::cli
