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
(declare-fun |obstacles[1]| () Bool)
(declare-fun |obstacles[2]| () Bool)
(declare-fun |obstacles[3]| () Bool)
(declare-fun |obstacles[4]| () Bool)
(declare-fun |obstacles[5]| () Bool)
(declare-fun |obstacles[6]| () Bool)
(declare-fun |obstacles[7]| () Bool)
(declare-fun |obstacles[8]| () Bool)
(declare-fun |obstacles[9]| () Bool)
(declare-fun |obstacles[10]| () Bool)
(declare-fun |obstacles[11]| () Bool)
(declare-fun reach () Real)
(declare-fun |trajectory[0]| () Bool)
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
 (let ((?x59 (+ (* (- 0.0 base_x) (- 0.0 base_x)) (* (- (/ 9.0 20.0) base_y) (- (/ 9.0 20.0) base_y)))))
 (=> (and |obstacles[0]| robot.link_diameter) (>= ?x59 (/ 62440089.0 20000000000.0)))))
(assert
 (let ((?x70 (+ (* (- (/ 9.0 10.0) base_x) (- (/ 9.0 10.0) base_x)) (* (- 0.0 base_y) (- 0.0 base_y)))))
 (=> (and |obstacles[1]| robot.link_diameter) (>= ?x70 (/ 86790049.0 20000000000.0)))))
(assert
 (let ((?x81 (+ (* (- (/ 699001.0 1000000.0) base_x) (- (/ 699001.0 1000000.0) base_x)) (* (- (/ 319967.0 1000000.0) base_y) (- (/ 319967.0 1000000.0) base_y)))))
 (=> (and |obstacles[2]| robot.link_diameter) (>= ?x81 (/ 86790049.0 20000000000.0)))))
(assert
 (let ((?x92 (+ (* (- (/ 649259.0 1000000.0) base_x) (- (/ 649259.0 1000000.0) base_x)) (* (- (/ 433123.0 1000000.0) base_y) (- (/ 433123.0 1000000.0) base_y)))))
 (=> (and |obstacles[3]| robot.link_diameter) (>= ?x92 (/ 86790049.0 20000000000.0)))))
(assert
 (let ((?x103 (+ (* (- (/ 108501.0 200000.0) base_x) (- (/ 108501.0 200000.0) base_x)) (* (- (/ 495431.0 1000000.0) base_y) (- (/ 495431.0 1000000.0) base_y)))))
 (=> (and |obstacles[4]| robot.link_diameter) (>= ?x103 (/ 86790049.0 20000000000.0)))))
(assert
 (let ((?x114 (+ (* (- (/ 104879.0 250000.0) base_x) (- (/ 104879.0 250000.0) base_x)) (* (- (/ 483091.0 1000000.0) base_y) (- (/ 483091.0 1000000.0) base_y)))))
 (=> (and |obstacles[5]| robot.link_diameter) (>= ?x114 (/ 86790049.0 20000000000.0)))))
(assert
 (let ((?x125 (+ (* (- (/ 327269.0 1000000.0) base_x) (- (/ 327269.0 1000000.0) base_x)) (* (- (/ 25051.0 62500.0) base_y) (- (/ 25051.0 62500.0) base_y)))))
 (=> (and |obstacles[6]| robot.link_diameter) (>= ?x125 (/ 86790049.0 20000000000.0)))))
(assert
 (let ((?x136 (+ (* (- (/ 300999.0 1000000.0) base_x) (- (/ 300999.0 1000000.0) base_x)) (* (- (/ 280033.0 1000000.0) base_y) (- (/ 280033.0 1000000.0) base_y)))))
 (=> (and |obstacles[7]| robot.link_diameter) (>= ?x136 (/ 86790049.0 20000000000.0)))))
(assert
 (let ((?x147 (+ (* (- (/ 350741.0 1000000.0) base_x) (- (/ 350741.0 1000000.0) base_x)) (* (- (/ 166877.0 1000000.0) base_y) (- (/ 166877.0 1000000.0) base_y)))))
 (=> (and |obstacles[8]| robot.link_diameter) (>= ?x147 (/ 86790049.0 20000000000.0)))))
(assert
 (let ((?x158 (+ (* (- (/ 91499.0 200000.0) base_x) (- (/ 91499.0 200000.0) base_x)) (* (- (/ 104569.0 1000000.0) base_y) (- (/ 104569.0 1000000.0) base_y)))))
 (=> (and |obstacles[9]| robot.link_diameter) (>= ?x158 (/ 86790049.0 20000000000.0)))))
(assert
 (let ((?x169 (+ (* (- (/ 145121.0 250000.0) base_x) (- (/ 145121.0 250000.0) base_x)) (* (- (/ 116909.0 1000000.0) base_y) (- (/ 116909.0 1000000.0) base_y)))))
 (=> (and |obstacles[10]| robot.link_diameter) (>= ?x169 (/ 86790049.0 20000000000.0)))))
(assert
 (let ((?x180 (+ (* (- (/ 672731.0 1000000.0) base_x) (- (/ 672731.0 1000000.0) base_x)) (* (- (/ 12449.0 62500.0) base_y) (- (/ 12449.0 62500.0) base_y)))))
 (=> (and |obstacles[11]| robot.link_diameter) (>= ?x180 (/ 86790049.0 20000000000.0)))))
(assert
 (= reach (+ (+ r1 r2) r3)))
(assert
 (let ((?x198 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x192 (- (/ 3.0 10.0) base_y)))
 (let ((?x193 (* ?x192 ?x192)))
 (let (($x201 (and |trajectory[0]|)))
 (=> $x201 (<= (+ (* (- (/ 29.0 50.0) base_x) (- (/ 29.0 50.0) base_x)) ?x193) ?x198)))))))
(assert
 (let ((?x198 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x206 (- (/ 71313708499.0 200000000000.0) base_y)))
 (let ((?x207 (* ?x206 ?x206)))
 (let ((?x204 (- (/ 111313708499.0 200000000000.0) base_x)))
 (let ((?x208 (* ?x204 ?x204)))
 (let (($x201 (and |trajectory[0]|)))
 (=> $x201 (<= (+ ?x208 ?x207) ?x198)))))))))
(assert
 (let ((?x198 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x213 (- (/ 1.0 2.0) base_x)))
 (let ((?x217 (* ?x213 ?x213)))
 (let (($x201 (and |trajectory[0]|)))
 (=> $x201 (<= (+ ?x217 (* (- (/ 19.0 50.0) base_y) (- (/ 19.0 50.0) base_y))) ?x198)))))))
(assert
 (let ((?x198 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x206 (- (/ 71313708499.0 200000000000.0) base_y)))
 (let ((?x207 (* ?x206 ?x206)))
 (let ((?x222 (- (/ 88686291501.0 200000000000.0) base_x)))
 (let ((?x223 (* ?x222 ?x222)))
 (let (($x201 (and |trajectory[0]|)))
 (=> $x201 (<= (+ ?x223 ?x207) ?x198)))))))))
(assert
 (let ((?x198 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x192 (- (/ 3.0 10.0) base_y)))
 (let ((?x193 (* ?x192 ?x192)))
 (let (($x201 (and |trajectory[0]|)))
 (=> $x201 (<= (+ (* (- (/ 21.0 50.0) base_x) (- (/ 21.0 50.0) base_x)) ?x193) ?x198)))))))
(assert
 (let ((?x198 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x234 (- (/ 48686291501.0 200000000000.0) base_y)))
 (let ((?x235 (* ?x234 ?x234)))
 (let ((?x222 (- (/ 88686291501.0 200000000000.0) base_x)))
 (let ((?x223 (* ?x222 ?x222)))
 (let (($x201 (and |trajectory[0]|)))
 (=> $x201 (<= (+ ?x223 ?x235) ?x198)))))))))
(assert
 (let ((?x198 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x213 (- (/ 1.0 2.0) base_x)))
 (let ((?x217 (* ?x213 ?x213)))
 (let (($x201 (and |trajectory[0]|)))
 (=> $x201 (<= (+ ?x217 (* (- (/ 11.0 50.0) base_y) (- (/ 11.0 50.0) base_y))) ?x198)))))))
(assert
 (let ((?x198 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x234 (- (/ 48686291501.0 200000000000.0) base_y)))
 (let ((?x235 (* ?x234 ?x234)))
 (let ((?x204 (- (/ 111313708499.0 200000000000.0) base_x)))
 (let ((?x208 (* ?x204 ?x204)))
 (let (($x201 (and |trajectory[0]|)))
 (=> $x201 (<= (+ ?x208 ?x235) ?x198)))))))))
(assert
 (let ((?x198 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x192 (- (/ 3.0 10.0) base_y)))
 (let ((?x193 (* ?x192 ?x192)))
 (let (($x201 (and |trajectory[0]|)))
 (=> $x201 (<= (+ (* (- (/ 29.0 50.0) base_x) (- (/ 29.0 50.0) base_x)) ?x193) ?x198)))))))
(assert
 (let (($x201 (and |trajectory[0]|)))
 (=> $x201 (>= (* 2.0 reach) (/ 1599999.0 10000000.0)))))
(check-sat-assuming (|robot.min_link_length| |robot.max_link_length| |robot.link_diameter| |base_regions| |obstacles[0]| |obstacles[1]| |obstacles[2]| |obstacles[3]| |obstacles[4]| |obstacles[5]| |obstacles[6]| |obstacles[7]| |obstacles[8]| |obstacles[9]| |obstacles[10]| |obstacles[11]| |trajectory[0]|))
