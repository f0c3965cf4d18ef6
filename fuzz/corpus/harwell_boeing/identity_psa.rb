identity                                                               |ID      
             2             1             1             0
psa                        3             3             3             0
(40I2)          (40I2)          
 1 2 3 4
 1 2 3
