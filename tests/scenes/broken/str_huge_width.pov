// error: 3:8: str()'s length 1.0000000000000001e+300 is out of range -10000 to 10000
// (issue 17, the reliability cases) once: a width of 1e300 cast to an integer.
#debug str(1, 1e300, 0)
