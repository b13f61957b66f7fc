// The memory budget's value as PENUMBRA_MEMORY_BUDGET gives it (scene/memory_budget.h). The
// refusal itself needs the programs' counting operator new: cli.scale checks it on penumbra.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "scene/memory_budget.h"

using namespace penumbra;

TEST(MemoryBudget, SizesReadInBinaryUnits) {
    std::size_t b = 0;
    EXPECT_TRUE(memory::parse_size("2G", b));
    EXPECT_EQ(b, std::size_t{2} << 30);
    EXPECT_TRUE(memory::parse_size("512M", b));
    EXPECT_EQ(b, std::size_t{512} << 20);
    EXPECT_TRUE(memory::parse_size("1.5GiB", b));
    EXPECT_EQ(b, std::size_t{3} << 29);
    EXPECT_TRUE(memory::parse_size("64k", b));
    EXPECT_EQ(b, std::size_t{64} << 10);
    EXPECT_TRUE(memory::parse_size("300000000", b));
    EXPECT_EQ(b, std::size_t{300000000});
    for (const char* bad : {"", "lots", "2X", "G", "1.5.2G", "-1G", "2GB x", "1e9"}) {
        b = 7;
        EXPECT_FALSE(memory::parse_size(bad, b)) << bad;
        EXPECT_EQ(b, 7u) << bad << ": left as it was";
    }
}

TEST(MemoryBudget, TheVariableSetsItOrIsNamed) {
    std::string error;
    unsetenv(memory::kBudgetVariable);
    ASSERT_TRUE(memory::budget_from_env(error));
    EXPECT_EQ(memory::budget(), memory::kDefaultBudget);
    setenv(memory::kBudgetVariable, "300M", 1);
    ASSERT_TRUE(memory::budget_from_env(error));
    EXPECT_EQ(memory::budget(), std::size_t{300} << 20);
    setenv(memory::kBudgetVariable, "none", 1);
    ASSERT_TRUE(memory::budget_from_env(error));
    EXPECT_EQ(memory::budget(), 0u);
    setenv(memory::kBudgetVariable, "512K", 1);  // under 1M: a typo more likely than a budget
    EXPECT_FALSE(memory::budget_from_env(error));
    EXPECT_NE(error.find("PENUMBRA_MEMORY_BUDGET=512K"), std::string::npos) << error;
    unsetenv(memory::kBudgetVariable);
    ASSERT_TRUE(memory::budget_from_env(error));
}
