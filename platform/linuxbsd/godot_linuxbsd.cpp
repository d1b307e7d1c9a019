/**************************************************************************/
/*  godot_linuxbsd.cpp                                                    */
/**************************************************************************/
/* Process entry point of bin/godot-area (Godot keeps main() per platform). */

#include "main/main.h"

int main(int argc, char **argv) {
	return Main::run(argc, argv);
}
