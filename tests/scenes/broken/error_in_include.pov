// error: include/broken_part.inc:3:13: undeclared identifier 'Missing'
#include "include/broken_part.inc"
// note: 2:1: included from here
