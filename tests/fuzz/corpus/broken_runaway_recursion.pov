// error: 3:3: nested more than 200 deep
#macro Forever(N)
  Forever(N + 1)
#end
Forever(1)

