integer stiffness                                                      |ISA     
             3             1             1             1
isa                        3             3             4             0
(40I2)          (40I2)          (13I6)              
 1 3 4 5
 1 2 2 3
  2000 -0.0  2000  1000
