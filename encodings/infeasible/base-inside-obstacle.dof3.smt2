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
(declare-fun reach () Real)
(declare-fun |trajectory[0]| () Bool)
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
 (let ((?x58 (+ (* (- 0.0 base_x) (- 0.0 base_x)) (* (- 0.0 base_y) (- 0.0 base_y)))))
 (=> (and |obstacles[0]| robot.link_diameter) (>= ?x58 (/ 369239769.0 20000000000.0)))))
(assert
 (= reach (+ (+ r1 r2) r3)))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x68 (- (/ 2.0 5.0) base_x)))
 (let ((?x72 (* ?x68 ?x68)))
 (let (($x79 (and |trajectory[0]|)))
 (=> $x79 (<= (+ ?x72 (* (- (/ 1.0 10.0) base_y) (- (/ 1.0 10.0) base_y))) ?x76)))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x68 (- (/ 2.0 5.0) base_x)))
 (let ((?x72 (* ?x68 ?x68)))
 (let (($x79 (and |trajectory[0]|)))
 (=> $x79 (<= (+ ?x72 (* (- (/ 1.0 8.0) base_y) (- (/ 1.0 8.0) base_y))) ?x76)))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x68 (- (/ 2.0 5.0) base_x)))
 (let ((?x72 (* ?x68 ?x68)))
 (let (($x79 (and |trajectory[0]|)))
 (=> $x79 (<= (+ ?x72 (* (- (/ 3.0 20.0) base_y) (- (/ 3.0 20.0) base_y))) ?x76)))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x68 (- (/ 2.0 5.0) base_x)))
 (let ((?x72 (* ?x68 ?x68)))
 (let (($x79 (and |trajectory[0]|)))
 (=> $x79 (<= (+ ?x72 (* (- (/ 7.0 40.0) base_y) (- (/ 7.0 40.0) base_y))) ?x76)))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x68 (- (/ 2.0 5.0) base_x)))
 (let ((?x72 (* ?x68 ?x68)))
 (let (($x79 (and |trajectory[0]|)))
 (=> $x79 (<= (+ ?x72 (* (- (/ 1.0 5.0) base_y) (- (/ 1.0 5.0) base_y))) ?x76)))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x68 (- (/ 2.0 5.0) base_x)))
 (let ((?x72 (* ?x68 ?x68)))
 (let (($x79 (and |trajectory[0]|)))
 (=> $x79 (<= (+ ?x72 (* (- (/ 9.0 40.0) base_y) (- (/ 9.0 40.0) base_y))) ?x76)))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x68 (- (/ 2.0 5.0) base_x)))
 (let ((?x72 (* ?x68 ?x68)))
 (let (($x79 (and |trajectory[0]|)))
 (=> $x79 (<= (+ ?x72 (* (- (/ 1.0 4.0) base_y) (- (/ 1.0 4.0) base_y))) ?x76)))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x68 (- (/ 2.0 5.0) base_x)))
 (let ((?x72 (* ?x68 ?x68)))
 (let (($x79 (and |trajectory[0]|)))
 (=> $x79 (<= (+ ?x72 (* (- (/ 11.0 40.0) base_y) (- (/ 11.0 40.0) base_y))) ?x76)))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x68 (- (/ 2.0 5.0) base_x)))
 (let ((?x72 (* ?x68 ?x68)))
 (let (($x127 (<= (+ ?x72 (* (- (/ 3.0 10.0) base_y) (- (/ 3.0 10.0) base_y))) ?x76)))
 (let (($x79 (and |trajectory[0]|)))
 (=> $x79 $x127)))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x68 (- (/ 2.0 5.0) base_x)))
 (let ((?x72 (* ?x68 ?x68)))
 (let (($x127 (<= (+ ?x72 (* (- (/ 3.0 10.0) base_y) (- (/ 3.0 10.0) base_y))) ?x76)))
 (let (($x130 (and |trajectory[1]|)))
 (=> $x130 $x127)))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x138 (+ (* (- (/ 9951963201.0 25000000000.0) base_x) (- (/ 9951963201.0 25000000000.0) base_x)) (* (- (/ 159754516101.0 500000000000.0) base_y) (- (/ 159754516101.0 500000000000.0) base_y)))))
 (let (($x130 (and |trajectory[1]|)))
 (=> $x130 (<= ?x138 ?x76))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x147 (+ (* (- (/ 392387953251.0 1000000000000.0) base_x) (- (/ 392387953251.0 1000000000000.0) base_x)) (* (- (/ 338268343237.0 1000000000000.0) base_y) (- (/ 338268343237.0 1000000000000.0) base_y)))))
 (let (($x130 (and |trajectory[1]|)))
 (=> $x130 (<= ?x147 ?x76))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x156 (+ (* (- (/ 38314696123.0 100000000000.0) base_x) (- (/ 38314696123.0 100000000000.0) base_x)) (* (- (/ 177778511651.0 500000000000.0) base_y) (- (/ 177778511651.0 500000000000.0) base_y)))))
 (let (($x130 (and |trajectory[1]|)))
 (=> $x130 (<= ?x156 ?x76))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x164 (+ (* (- (/ 370710678119.0 1000000000000.0) base_x) (- (/ 370710678119.0 1000000000000.0) base_x)) (* (- (/ 370710678119.0 1000000000000.0) base_y) (- (/ 370710678119.0 1000000000000.0) base_y)))))
 (let (($x130 (and |trajectory[1]|)))
 (=> $x130 (<= ?x164 ?x76))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x171 (+ (* (- (/ 177778511651.0 500000000000.0) base_x) (- (/ 177778511651.0 500000000000.0) base_x)) (* (- (/ 38314696123.0 100000000000.0) base_y) (- (/ 38314696123.0 100000000000.0) base_y)))))
 (let (($x130 (and |trajectory[1]|)))
 (=> $x130 (<= ?x171 ?x76))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x178 (+ (* (- (/ 338268343237.0 1000000000000.0) base_x) (- (/ 338268343237.0 1000000000000.0) base_x)) (* (- (/ 392387953251.0 1000000000000.0) base_y) (- (/ 392387953251.0 1000000000000.0) base_y)))))
 (let (($x130 (and |trajectory[1]|)))
 (=> $x130 (<= ?x178 ?x76))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x185 (+ (* (- (/ 159754516101.0 500000000000.0) base_x) (- (/ 159754516101.0 500000000000.0) base_x)) (* (- (/ 9951963201.0 25000000000.0) base_y) (- (/ 9951963201.0 25000000000.0) base_y)))))
 (let (($x130 (and |trajectory[1]|)))
 (=> $x130 (<= ?x185 ?x76))))))
(assert
 (let ((?x76 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x192 (+ (* (- (/ 3.0 10.0) base_x) (- (/ 3.0 10.0) base_x)) (* (- (/ 2.0 5.0) base_y) (- (/ 2.0 5.0) base_y)))))
 (let (($x130 (and |trajectory[1]|)))
 (=> $x130 (<= ?x192 ?x76))))))
(assert
 (let (($x79 (and |trajectory[0]|)))
 (=> $x79 (>= (* 2.0 reach) (/ 1999999.0 10000000.0)))))
(assert
 (=> (and |trajectory[0]| |trajectory[1]|) (>= (* 2.0 reach) (/ 316227666017.0 1000000000000.0))))
(assert
 (let (($x130 (and |trajectory[1]|)))
 (=> $x130 (>= (* 2.0 reach) (/ 141421256237.0 1000000000000.0)))))
(check-sat-assuming (|robot.min_link_length| |robot.max_link_length| |robot.link_diameter| |base_regions| |obstacles[0]| |trajectory[0]| |trajectory[1]|))
