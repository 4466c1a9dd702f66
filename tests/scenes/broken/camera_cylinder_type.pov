// error: 3:3: invalid cylinder camera type, valid are types 1 to 4
camera {
  cylinder 5
  location <0, 0, -5>
}
