/* placeholder, replaced below */
#include "study.h"
int cmd_table(int argc, char **argv) { (void)argc; (void)argv; return 2; }
