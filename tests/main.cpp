// The tests' main: Catch's own, except that a run whose filter matches no test fails. ctest runs
// each test by its name; a name that reached it cut short matched nothing and passed, and so more
// than a hundred tests once ran in no CI (tests/check_test_names.sh tells why).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

int main(int argc, char *argv[]) {
    Catch::Session session;
    session.configData().warnings = Catch::WarnAbout::NoTests;
    if (const int error = session.applyCommandLine(argc, argv)) return error;
    return session.run();
}
