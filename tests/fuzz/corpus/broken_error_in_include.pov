// error: include/broken_part.inc:3:13: undeclared identifier 'Missing'
// note: 2:1: included from here

