// error: 3:21: arrays and strings would hold more than 2048.0 MiB
// 10^8 slots of 24 bytes are past the default 2 GiB (this array once took 4.8 GB).
#declare Big = array[100000000]
