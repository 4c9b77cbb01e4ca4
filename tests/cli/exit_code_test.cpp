// The library's error kinds become the exit codes docs/cli.md documents only in cli/.
#include "exit_code.hpp"
#include <gtest/gtest.h>

TEST(ExitCode, EachErrorKindHasItsDocumentedCode) {
    EXPECT_EQ(spt::cli::exit_code(spt::ErrorKind::Usage), 1);
    EXPECT_EQ(spt::cli::exit_code(spt::ErrorKind::BadInput), 2);
    EXPECT_EQ(spt::cli::exit_code(spt::ErrorKind::CannotWrite), 3);
}
