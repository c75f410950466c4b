// TextSink: where a streaming writer's output goes. The writers of outputs
// that grow with the graph (io::write_graph, io::write_faces_of,
// io::write_dump, io::write_dump_of, check::write_reference_answer) hand
// their text to a sink in consecutive pieces as they produce it, so that an
// output of hundreds of megabytes is never held whole: the caller writes each
// piece to a file, a pipe or a socket. Pieces come in order, none empty and
// none over 16 KiB; concatenated they are exactly the text the
// string-returning form of the same writer returns.
//
// A sink may throw (a failed write): the writer stops there and the exception
// reaches its caller. What the sink took before stays taken; the writers
// hold nothing that needs undoing.
#pragma once

#include <functional>
#include <string_view>

namespace dcel::io {

using TextSink = std::function<void(std::string_view)>;

}  // namespace dcel::io
