// error: 4:1: #include nested more than 100 deep
// A file that includes itself stops at the include depth limit
// (--max-include-depth N).
#include "include_itself.pov"
