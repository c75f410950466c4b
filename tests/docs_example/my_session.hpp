// Your DCEL as the session helpers drive it (dcel/testing/check_testing_sessions.hpp):
// made from the start graph, then answering one step at a time. In a real
// project this is your adapter; the docs example's two stand-ins are in
// session_stand_in.cpp.
#pragma once

#include <memory>

#include "dcel/graph.hpp"
#include "dcel/testing/session_implementation.hpp"

std::unique_ptr<dcel::testing::SessionImplementation> my_session(const dcel::PlanarGraph& start);
