// error: 3:9: torus needs
// povray: line 3: Parse Error: Expected 'numeric expression', } found instead
torus { 1 }

