#!/usr/bin/env bash
# Installs every Debian package the build, the tests and the charts need.
# The single install list of the project: nothing is installed by hand.
# Only packages that are missing are installed, so a second run is quick.
set -euo pipefail

PACKAGES=(
	# Build.
	g++ scons pkg-config
	# Vulkan: loader, headers, software driver (lavapipe), validation layers, vulkaninfo.
	libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
	# Shader compilation at run time and SPIR-V reflection.
	glslang-dev glslang-tools spirv-tools
	# Image output and scene import.
	libopenexr-dev libpng-dev libtinygltf-dev nlohmann-json3-dev libstb-dev libwebp-dev
	# CPU reference renderer (ray tracing).
	libembree-dev
	# Tests, and the format check (misc/scripts/check_format.sh).
	doctest-dev clang-format
	# Sanitizer and fuzz job (misc/scripts/sanitize_fuzz.sh, `scons fuzz=yes`): clang with ASan, UBSan, libFuzzer.
	clang libclang-rt-dev
	# Charts.
	python3-matplotlib python3-numpy
	# Python module godot_area (modules/python), built for and tested with /usr/bin/python3.
	python3-dev python3-pybind11 pybind11-dev
	# Python tests (pytest, run with /usr/bin/python3).
	python3-pytest
	# Editor window (GLFW + Dear ImGui) and its tests under a virtual X server with synthetic input.
	libglfw3-dev libimgui-dev xvfb xdotool
)

missing=()
for p in "${PACKAGES[@]}"; do
	if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
		missing+=("$p")
	fi
done

if [ ${#missing[@]} -eq 0 ]; then
	echo "install_deps: all ${#PACKAGES[@]} packages present."
	exit 0
fi

echo "install_deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" != "0" ]; then
	SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
