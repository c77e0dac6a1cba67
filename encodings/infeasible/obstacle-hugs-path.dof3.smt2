; 
(set-info :status unknown)
(declare-fun r1 () Real)
(declare-fun robot.min_link_length () Bool)
(declare-fun robot.max_link_length () Bool)
(declare-fun r2 () Real)
(declare-fun r3 () Real)
(declare-fun robot.link_diameter () Bool)
(declare-fun base_y () Real)
(declare-fun base_x () Real)
(declare-fun in_region_0 () Bool)
(declare-fun base_regions () Bool)
(declare-fun |obstacles[0]| () Bool)
(declare-fun |trajectory[0]| () Bool)
(declare-fun reach () Real)
(declare-fun |trajectory[1]| () Bool)
(assert
 (> r1 0.0))
(assert
 (let (($x16 (and robot.min_link_length)))
 (=> $x16 (>= r1 (/ 499999.0 10000000.0)))))
(assert
 (let (($x21 (and robot.max_link_length)))
 (=> $x21 (<= r1 (/ 10000001.0 10000000.0)))))
(assert
 (> r2 0.0))
(assert
 (let (($x16 (and robot.min_link_length)))
 (=> $x16 (>= r2 (/ 499999.0 10000000.0)))))
(assert
 (let (($x21 (and robot.max_link_length)))
 (=> $x21 (<= r2 (/ 10000001.0 10000000.0)))))
(assert
 (> r3 0.0))
(assert
 (let (($x16 (and robot.min_link_length)))
 (=> $x16 (>= r3 (/ 499999.0 10000000.0)))))
(assert
 (let (($x21 (and robot.max_link_length)))
 (=> $x21 (<= r3 (/ 10000001.0 10000000.0)))))
(assert
 (=> (and robot.link_diameter) (>= r3 (/ 317499.0 10000000.0))))
(assert
 (let (($x45 (and (and (>= base_x (- (/ 500001.0 10000000.0))) (<= base_x (/ 500001.0 10000000.0))) (>= base_y (- (/ 500001.0 10000000.0))))))
 (=> in_region_0 (and $x45 (<= base_y (/ 500001.0 10000000.0))))))
(assert
 (=> (and base_regions) (or in_region_0)))
(assert
 (let ((?x57 (- (/ 1.0 4.0) base_y)))
 (let ((?x58 (* ?x57 ?x57)))
 (let ((?x55 (- (/ 2.0 5.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[0]| robot.link_diameter) (>= (+ ?x59 ?x58) (/ 62440089.0 20000000000.0))))))))
(assert
 (=> (and |trajectory[0]| |obstacles[0]| robot.link_diameter) false))
(assert
 (= reach (+ (+ r1 r2) r3)))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x75 (- (/ 1.0 5.0) base_y)))
 (let ((?x76 (* ?x75 ?x75)))
 (let (($x83 (and |trajectory[0]|)))
 (=> $x83 (<= (+ (* (- (/ 3.0 10.0) base_x) (- (/ 3.0 10.0) base_x)) ?x76) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x75 (- (/ 1.0 5.0) base_y)))
 (let ((?x76 (* ?x75 ?x75)))
 (let (($x83 (and |trajectory[0]|)))
 (=> $x83 (<= (+ (* (- (/ 13.0 40.0) base_x) (- (/ 13.0 40.0) base_x)) ?x76) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x75 (- (/ 1.0 5.0) base_y)))
 (let ((?x76 (* ?x75 ?x75)))
 (let (($x83 (and |trajectory[0]|)))
 (=> $x83 (<= (+ (* (- (/ 7.0 20.0) base_x) (- (/ 7.0 20.0) base_x)) ?x76) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x75 (- (/ 1.0 5.0) base_y)))
 (let ((?x76 (* ?x75 ?x75)))
 (let (($x83 (and |trajectory[0]|)))
 (=> $x83 (<= (+ (* (- (/ 3.0 8.0) base_x) (- (/ 3.0 8.0) base_x)) ?x76) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x75 (- (/ 1.0 5.0) base_y)))
 (let ((?x76 (* ?x75 ?x75)))
 (let ((?x55 (- (/ 2.0 5.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (let (($x83 (and |trajectory[0]|)))
 (=> $x83 (<= (+ ?x59 ?x76) ?x81)))))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x75 (- (/ 1.0 5.0) base_y)))
 (let ((?x76 (* ?x75 ?x75)))
 (let (($x83 (and |trajectory[0]|)))
 (=> $x83 (<= (+ (* (- (/ 17.0 40.0) base_x) (- (/ 17.0 40.0) base_x)) ?x76) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x75 (- (/ 1.0 5.0) base_y)))
 (let ((?x76 (* ?x75 ?x75)))
 (let (($x83 (and |trajectory[0]|)))
 (=> $x83 (<= (+ (* (- (/ 9.0 20.0) base_x) (- (/ 9.0 20.0) base_x)) ?x76) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x75 (- (/ 1.0 5.0) base_y)))
 (let ((?x76 (* ?x75 ?x75)))
 (let (($x83 (and |trajectory[0]|)))
 (=> $x83 (<= (+ (* (- (/ 19.0 40.0) base_x) (- (/ 19.0 40.0) base_x)) ?x76) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x75 (- (/ 1.0 5.0) base_y)))
 (let ((?x76 (* ?x75 ?x75)))
 (let ((?x125 (- (/ 1.0 2.0) base_x)))
 (let ((?x126 (* ?x125 ?x125)))
 (let (($x128 (<= (+ ?x126 ?x76) ?x81)))
 (let (($x83 (and |trajectory[0]|)))
 (=> $x83 $x128)))))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x75 (- (/ 1.0 5.0) base_y)))
 (let ((?x76 (* ?x75 ?x75)))
 (let ((?x125 (- (/ 1.0 2.0) base_x)))
 (let ((?x126 (* ?x125 ?x125)))
 (let (($x128 (<= (+ ?x126 ?x76) ?x81)))
 (let (($x131 (and |trajectory[1]|)))
 (=> $x131 $x128)))))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x125 (- (/ 1.0 2.0) base_x)))
 (let ((?x126 (* ?x125 ?x125)))
 (let (($x131 (and |trajectory[1]|)))
 (=> $x131 (<= (+ ?x126 (* (- (/ 9.0 40.0) base_y) (- (/ 9.0 40.0) base_y))) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x57 (- (/ 1.0 4.0) base_y)))
 (let ((?x58 (* ?x57 ?x57)))
 (let ((?x125 (- (/ 1.0 2.0) base_x)))
 (let ((?x126 (* ?x125 ?x125)))
 (let (($x131 (and |trajectory[1]|)))
 (=> $x131 (<= (+ ?x126 ?x58) ?x81)))))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x125 (- (/ 1.0 2.0) base_x)))
 (let ((?x126 (* ?x125 ?x125)))
 (let (($x131 (and |trajectory[1]|)))
 (=> $x131 (<= (+ ?x126 (* (- (/ 11.0 40.0) base_y) (- (/ 11.0 40.0) base_y))) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x125 (- (/ 1.0 2.0) base_x)))
 (let ((?x126 (* ?x125 ?x125)))
 (let (($x131 (and |trajectory[1]|)))
 (=> $x131 (<= (+ ?x126 (* (- (/ 3.0 10.0) base_y) (- (/ 3.0 10.0) base_y))) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x125 (- (/ 1.0 2.0) base_x)))
 (let ((?x126 (* ?x125 ?x125)))
 (let (($x131 (and |trajectory[1]|)))
 (=> $x131 (<= (+ ?x126 (* (- (/ 13.0 40.0) base_y) (- (/ 13.0 40.0) base_y))) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x125 (- (/ 1.0 2.0) base_x)))
 (let ((?x126 (* ?x125 ?x125)))
 (let (($x131 (and |trajectory[1]|)))
 (=> $x131 (<= (+ ?x126 (* (- (/ 7.0 20.0) base_y) (- (/ 7.0 20.0) base_y))) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x125 (- (/ 1.0 2.0) base_x)))
 (let ((?x126 (* ?x125 ?x125)))
 (let (($x131 (and |trajectory[1]|)))
 (=> $x131 (<= (+ ?x126 (* (- (/ 3.0 8.0) base_y) (- (/ 3.0 8.0) base_y))) ?x81)))))))
(assert
 (let ((?x81 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x125 (- (/ 1.0 2.0) base_x)))
 (let ((?x126 (* ?x125 ?x125)))
 (let (($x131 (and |trajectory[1]|)))
 (=> $x131 (<= (+ ?x126 (* (- (/ 2.0 5.0) base_y) (- (/ 2.0 5.0) base_y))) ?x81)))))))
(assert
 (let ((?x175 (* 2.0 reach)))
 (let (($x176 (>= ?x175 (/ 1999999.0 10000000.0))))
 (let (($x83 (and |trajectory[0]|)))
 (=> $x83 $x176)))))
(assert
 (=> (and |trajectory[0]| |trajectory[1]|) (>= (* 2.0 reach) (/ 11313704499.0 40000000000.0))))
(assert
 (let ((?x175 (* 2.0 reach)))
 (let (($x176 (>= ?x175 (/ 1999999.0 10000000.0))))
 (let (($x131 (and |trajectory[1]|)))
 (=> $x131 $x176)))))
(check-sat-assuming (|robot.min_link_length| |robot.max_link_length| |robot.link_diameter| |base_regions| |obstacles[0]| |trajectory[0]| |trajectory[1]|))
