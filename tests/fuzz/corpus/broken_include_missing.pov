// error: 2:1: include file 'no_such_file.inc' not found

