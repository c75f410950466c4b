// The property-test runner. ctest sets RC_PARAMS (a fixed seed and the
// default case count); DCEL_PROPERTY_CASES, when set, raises the case count
// for long runs without touching the seed:
//     DCEL_PROPERTY_CASES=5000 ctest --test-dir build -R prop_
// RapidCheck reads RC_PARAMS once, at its first property, so it is amended
// here before any test runs.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    if (const char* cases = std::getenv("DCEL_PROPERTY_CASES"); cases != nullptr && *cases != '\0') {
        const char* base = std::getenv("RC_PARAMS");
        // Later keys win in RapidCheck's parser, so appending overrides.
        const std::string params = std::string(base != nullptr ? base : "") + " max_success=" + cases;
        setenv("RC_PARAMS", params.c_str(), 1);
        std::cerr << "RC_PARAMS=" << params << "\n";
    }
    return RUN_ALL_TESTS();
}
