// Placeholder until the command line lands.
#include <cstdio>
int main() {
  std::puts("darc " DARC_VERSION);
  return 0;
}
