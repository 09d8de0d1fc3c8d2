#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"tierlift: lift Direct3D shader assembly onto Vulkan"};
  app.set_version_flag("--version", std::string("tierlift ") + TIERLIFT_VERSION);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
