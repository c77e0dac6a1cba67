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
(declare-fun reach () Real)
(declare-fun |strokes[0][0]| () Bool)
(declare-fun |strokes[1][0]| () Bool)
(assert
 (> r1 0.0))
(assert
 (let (($x16 (and robot.min_link_length)))
 (=> $x16 (>= r1 (/ 499999.0 10000000.0)))))
(assert
 (let (($x21 (and robot.max_link_length)))
 (=> $x21 (<= r1 (/ 4000001.0 10000000.0)))))
(assert
 (> r2 0.0))
(assert
 (let (($x16 (and robot.min_link_length)))
 (=> $x16 (>= r2 (/ 499999.0 10000000.0)))))
(assert
 (let (($x21 (and robot.max_link_length)))
 (=> $x21 (<= r2 (/ 4000001.0 10000000.0)))))
(assert
 (> r3 0.0))
(assert
 (let (($x16 (and robot.min_link_length)))
 (=> $x16 (>= r3 (/ 499999.0 10000000.0)))))
(assert
 (let (($x21 (and robot.max_link_length)))
 (=> $x21 (<= r3 (/ 4000001.0 10000000.0)))))
(assert
 (=> (and robot.link_diameter) (>= r3 (/ 317499.0 10000000.0))))
(assert
 (let (($x45 (and (and (>= base_x (- (/ 500001.0 10000000.0))) (<= base_x (/ 500001.0 10000000.0))) (>= base_y (- (/ 500001.0 10000000.0))))))
 (=> in_region_0 (and $x45 (<= base_y (/ 500001.0 10000000.0))))))
(assert
 (=> (and base_regions) (or in_region_0)))
(assert
 (= reach (+ (+ r1 r2) r3)))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x68 (and |strokes[0][0]|)))
 (=> $x68 (<= (+ (* (- (/ 3.0 10.0) base_x) (- (/ 3.0 10.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x68 (and |strokes[0][0]|)))
 (=> $x68 (<= (+ (* (- (/ 5.0 16.0) base_x) (- (/ 5.0 16.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x68 (and |strokes[0][0]|)))
 (=> $x68 (<= (+ (* (- (/ 13.0 40.0) base_x) (- (/ 13.0 40.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x68 (and |strokes[0][0]|)))
 (=> $x68 (<= (+ (* (- (/ 27.0 80.0) base_x) (- (/ 27.0 80.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x68 (and |strokes[0][0]|)))
 (=> $x68 (<= (+ (* (- (/ 7.0 20.0) base_x) (- (/ 7.0 20.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x68 (and |strokes[0][0]|)))
 (=> $x68 (<= (+ (* (- (/ 29.0 80.0) base_x) (- (/ 29.0 80.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x68 (and |strokes[0][0]|)))
 (=> $x68 (<= (+ (* (- (/ 3.0 8.0) base_x) (- (/ 3.0 8.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x68 (and |strokes[0][0]|)))
 (=> $x68 (<= (+ (* (- (/ 31.0 80.0) base_x) (- (/ 31.0 80.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x68 (and |strokes[0][0]|)))
 (=> $x68 (<= (+ (* (- (/ 2.0 5.0) base_x) (- (/ 2.0 5.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x124 (and |strokes[1][0]|)))
 (=> $x124 (<= (+ (* (- (/ 3.0 2.0) base_x) (- (/ 3.0 2.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x124 (and |strokes[1][0]|)))
 (=> $x124 (<= (+ (* (- (/ 121.0 80.0) base_x) (- (/ 121.0 80.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x124 (and |strokes[1][0]|)))
 (=> $x124 (<= (+ (* (- (/ 61.0 40.0) base_x) (- (/ 61.0 40.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x124 (and |strokes[1][0]|)))
 (=> $x124 (<= (+ (* (- (/ 123.0 80.0) base_x) (- (/ 123.0 80.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x124 (and |strokes[1][0]|)))
 (=> $x124 (<= (+ (* (- (/ 31.0 20.0) base_x) (- (/ 31.0 20.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x124 (and |strokes[1][0]|)))
 (=> $x124 (<= (+ (* (- (/ 25.0 16.0) base_x) (- (/ 25.0 16.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x124 (and |strokes[1][0]|)))
 (=> $x124 (<= (+ (* (- (/ 63.0 40.0) base_x) (- (/ 63.0 40.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x124 (and |strokes[1][0]|)))
 (=> $x124 (<= (+ (* (- (/ 127.0 80.0) base_x) (- (/ 127.0 80.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x65 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x59 (- 0.0 base_y)))
 (let ((?x60 (* ?x59 ?x59)))
 (let (($x124 (and |strokes[1][0]|)))
 (=> $x124 (<= (+ (* (- (/ 8.0 5.0) base_x) (- (/ 8.0 5.0) base_x)) ?x60) ?x65)))))))
(assert
 (let ((?x176 (* 2.0 reach)))
 (let (($x177 (>= ?x176 (/ 999999.0 10000000.0))))
 (let (($x68 (and |strokes[0][0]|)))
 (=> $x68 $x177)))))
(assert
 (=> (and |strokes[0][0]| |strokes[1][0]|) (>= (* 2.0 reach) (/ 12999999.0 10000000.0))))
(assert
 (let ((?x176 (* 2.0 reach)))
 (let (($x177 (>= ?x176 (/ 999999.0 10000000.0))))
 (let (($x124 (and |strokes[1][0]|)))
 (=> $x124 $x177)))))
(check-sat-assuming (|robot.min_link_length| |robot.max_link_length| |robot.link_diameter| |base_regions| |strokes[0][0]| |strokes[1][0]|))
