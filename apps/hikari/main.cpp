#include <cstdio>

#include "hikari/version.h"

int main() {
    std::printf("hikari %s\n", hikari::k_version);
    return 0;
}
