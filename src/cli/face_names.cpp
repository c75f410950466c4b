#include "face_names.hpp"

#include <optional>
#include <sstream>

#include "cli_support.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/locate.hpp"

namespace dcel::cli {
namespace {

// Up to this many names, a scan per name (O(V + E) each) beats building
// the trapezoidal map (O((V + E) log(V + E)) expected).
constexpr std::size_t kScannedNames = 4;

}  // namespace

std::vector<FaceId> name_faces(const Dcel& d, const std::vector<NamedPoint>& names, const std::string& source,
                               FaceNames& out) {
    std::optional<PointLocator> locator;
    if (names.size() > kScannedNames) locator.emplace(d);
    std::vector<FaceId> faces;
    faces.reserve(names.size());
    for (const NamedPoint& n : names) {
        const Location l = locator ? locator->locate(n.at) : locate_by_scan(d, n.at);
        if (l.kind != Location::Kind::Face) {
            std::ostringstream where;
            where << l;
            throw InvalidInput(InputErrorKind::BadCoordinate, source + ": the point " + format_point(n.at) + " for " +
                                                                  quote_for_message(n.name) + " is " + where.str() +
                                                                  ", not inside a face; give a point inside it");
        }
        out[l.face] = n.name;
        faces.push_back(l.face);
    }
    return faces;
}

std::vector<NamedPoint> load_face_names(const std::string& path) {
    if (path.empty()) return {};
    const std::string text = read_input(path);
    return with_source(path, [&] { return read_face_names(text); });
}

}  // namespace dcel::cli
