// SPDX-License-Identifier: GPL-3.0-or-later
// The program that calls remesh.cpp through the shared library remesh_plugin.
int remesh_main(int argc, char** argv);

int main(int argc, char** argv) { return remesh_main(argc, argv); }
