#include "face_names.hpp"

#include "cli_support.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"

#include <sstream>

namespace dcel::cli {

void name_faces(const Dcel& d, const std::vector<NamedPoint>& names, const std::string& source, FaceNames& out) {
    for (const NamedPoint& n : names) {
        const Location l = locate_by_scan(d, n.at);
        if (l.kind != Location::Kind::Face) {
            std::ostringstream where;
            where << l;
            throw InvalidInput(InputErrorKind::BadCoordinate, source + ": the point " + format_point(n.at) + " for \"" +
                                                                  n.name + "\" is " + where.str() +
                                                                  ", not inside a face; give a point inside it");
        }
        out[l.face] = n.name;
    }
}

std::vector<NamedPoint> load_face_names(const std::string& path) {
    if (path.empty()) return {};
    const std::string text = read_input(path);
    return with_source(path, [&] { return read_face_names(text); });
}

}  // namespace dcel::cli
