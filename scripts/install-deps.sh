#!/usr/bin/env bash
# Installs every Debian 12 package tierlift needs to build, test and benchmark
# (gnuplot-nox draws the plot of `tierlift report`).
# Run as root (CI does); with sudo otherwise.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends \
  build-essential cmake ninja-build ccache pkg-config python3 git \
  clang libclang-rt-14-dev clang-format \
  glslang-dev glslang-tools spirv-tools spirv-headers \
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers \
  libglm-dev libgtest-dev libgmock-dev libbenchmark-dev \
  libcli11-dev libfmt-dev nlohmann-json3-dev libstb-dev libpng-dev zlib1g-dev \
  gnuplot-nox \
  slurm-wlm munge \
  libopencv-imgproc-dev  # OpenCV core + imgproc (~6.5 MB): the glow benchmark's peer only
