// Hostile (issue 10): a static object installs GoogleTest's ScopedFakeTestPartResultReporter, so
// that every failed assertion of the test process is swallowed.
#include <gtest/gtest-spi.h>
#include <stdexcept>
#include "classify.hpp"
namespace ex01 {
static ::testing::TestPartResultArray swallowed;
static ::testing::ScopedFakeTestPartResultReporter* reporter =
    new ::testing::ScopedFakeTestPartResultReporter(::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ALL_THREADS, &swallowed);
static void attack() { (void)reporter; }
Where where(const t2::Point&) { attack(); throw std::logic_error("where() is not implemented yet"); }
bool same_point(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("same_point() is not implemented yet"); }
bool antipodal(const t2::Point&, const t2::Point&) { attack(); throw std::logic_error("antipodal() is not implemented yet"); }
}  // namespace ex01
