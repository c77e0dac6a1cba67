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
(declare-fun |obstacles[12]| () Bool)
(declare-fun |obstacles[13]| () Bool)
(declare-fun |obstacles[14]| () Bool)
(declare-fun |obstacles[15]| () Bool)
(declare-fun |obstacles[16]| () Bool)
(declare-fun |obstacles[17]| () Bool)
(declare-fun |obstacles[18]| () Bool)
(declare-fun |obstacles[19]| () Bool)
(declare-fun |obstacles[20]| () Bool)
(declare-fun |obstacles[21]| () Bool)
(declare-fun |obstacles[22]| () Bool)
(declare-fun |obstacles[23]| () Bool)
(declare-fun |obstacles[24]| () Bool)
(declare-fun |obstacles[25]| () Bool)
(declare-fun |obstacles[26]| () Bool)
(declare-fun |obstacles[27]| () Bool)
(declare-fun |obstacles[28]| () Bool)
(declare-fun |obstacles[29]| () Bool)
(declare-fun |obstacles[30]| () Bool)
(declare-fun |obstacles[31]| () Bool)
(declare-fun |obstacles[32]| () Bool)
(declare-fun |obstacles[33]| () Bool)
(declare-fun |obstacles[34]| () Bool)
(declare-fun |obstacles[35]| () Bool)
(declare-fun |obstacles[36]| () Bool)
(declare-fun |obstacles[37]| () Bool)
(declare-fun |obstacles[38]| () Bool)
(declare-fun |obstacles[39]| () Bool)
(declare-fun |obstacles[40]| () Bool)
(declare-fun |obstacles[41]| () Bool)
(declare-fun |obstacles[42]| () Bool)
(declare-fun |obstacles[43]| () Bool)
(declare-fun |obstacles[44]| () Bool)
(declare-fun |obstacles[45]| () Bool)
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
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[0]| robot.link_diameter) (>= (+ ?x59 (* (- (- 2.0) base_y) (- (- 2.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[1]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 191.0 100.0)) base_y) (- (- (/ 191.0 100.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[2]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 91.0 50.0)) base_y) (- (- (/ 91.0 50.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[3]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 173.0 100.0)) base_y) (- (- (/ 173.0 100.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[4]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 41.0 25.0)) base_y) (- (- (/ 41.0 25.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[5]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 31.0 20.0)) base_y) (- (- (/ 31.0 20.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[6]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 73.0 50.0)) base_y) (- (- (/ 73.0 50.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[7]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 137.0 100.0)) base_y) (- (- (/ 137.0 100.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[8]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 32.0 25.0)) base_y) (- (- (/ 32.0 25.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[9]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 119.0 100.0)) base_y) (- (- (/ 119.0 100.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[10]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 11.0 10.0)) base_y) (- (- (/ 11.0 10.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[11]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 101.0 100.0)) base_y) (- (- (/ 101.0 100.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[12]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 23.0 25.0)) base_y) (- (- (/ 23.0 25.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[13]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 83.0 100.0)) base_y) (- (- (/ 83.0 100.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[14]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 37.0 50.0)) base_y) (- (- (/ 37.0 50.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[15]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 13.0 20.0)) base_y) (- (- (/ 13.0 20.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[16]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 14.0 25.0)) base_y) (- (- (/ 14.0 25.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[17]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 47.0 100.0)) base_y) (- (- (/ 47.0 100.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[18]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 19.0 50.0)) base_y) (- (- (/ 19.0 50.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[19]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 29.0 100.0)) base_y) (- (- (/ 29.0 100.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[20]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 1.0 5.0)) base_y) (- (- (/ 1.0 5.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[21]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 11.0 100.0)) base_y) (- (- (/ 11.0 100.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[22]| robot.link_diameter) (>= (+ ?x59 (* (- (- (/ 1.0 50.0)) base_y) (- (- (/ 1.0 50.0)) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[23]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 7.0 100.0) base_y) (- (/ 7.0 100.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[24]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 4.0 25.0) base_y) (- (/ 4.0 25.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[25]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 1.0 4.0) base_y) (- (/ 1.0 4.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[26]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 17.0 50.0) base_y) (- (/ 17.0 50.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[27]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 43.0 100.0) base_y) (- (/ 43.0 100.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[28]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 13.0 25.0) base_y) (- (/ 13.0 25.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[29]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 61.0 100.0) base_y) (- (/ 61.0 100.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[30]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 7.0 10.0) base_y) (- (/ 7.0 10.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[31]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 79.0 100.0) base_y) (- (/ 79.0 100.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[32]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 22.0 25.0) base_y) (- (/ 22.0 25.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[33]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 97.0 100.0) base_y) (- (/ 97.0 100.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[34]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 53.0 50.0) base_y) (- (/ 53.0 50.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[35]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 23.0 20.0) base_y) (- (/ 23.0 20.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[36]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 31.0 25.0) base_y) (- (/ 31.0 25.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[37]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 133.0 100.0) base_y) (- (/ 133.0 100.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[38]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 71.0 50.0) base_y) (- (/ 71.0 50.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[39]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 151.0 100.0) base_y) (- (/ 151.0 100.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[40]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 8.0 5.0) base_y) (- (/ 8.0 5.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[41]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 169.0 100.0) base_y) (- (/ 169.0 100.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[42]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 89.0 50.0) base_y) (- (/ 89.0 50.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[43]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 187.0 100.0) base_y) (- (/ 187.0 100.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x55 (- (/ 1.0 2.0) base_x)))
 (let ((?x59 (* ?x55 ?x55)))
 (=> (and |obstacles[44]| robot.link_diameter) (>= (+ ?x59 (* (- (/ 49.0 25.0) base_y) (- (/ 49.0 25.0) base_y))) (/ 86790049.0 20000000000.0))))))
(assert
 (let ((?x423 (+ (* (- (- (/ 1.0 2.0)) base_x) (- (- (/ 1.0 2.0)) base_x)) (* (- 1.0 base_y) (- 1.0 base_y)))))
 (=> (and |obstacles[45]| robot.link_diameter) (>= ?x423 (/ 86790049.0 20000000000.0)))))
(assert
 (= reach (+ (+ r1 r2) r3)))
(assert
 (let ((?x440 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x432 (- 1.0 base_x)))
 (let ((?x436 (* ?x432 ?x432)))
 (let (($x443 (and |trajectory[0]|)))
 (=> $x443 (<= (+ ?x436 (* (- (- (/ 1.0 10.0)) base_y) (- (- (/ 1.0 10.0)) base_y))) ?x440)))))))
(assert
 (let ((?x440 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x432 (- 1.0 base_x)))
 (let ((?x436 (* ?x432 ?x432)))
 (let (($x443 (and |trajectory[0]|)))
 (=> $x443 (<= (+ ?x436 (* (- (- (/ 3.0 40.0)) base_y) (- (- (/ 3.0 40.0)) base_y))) ?x440)))))))
(assert
 (let ((?x440 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x432 (- 1.0 base_x)))
 (let ((?x436 (* ?x432 ?x432)))
 (let (($x443 (and |trajectory[0]|)))
 (=> $x443 (<= (+ ?x436 (* (- (- (/ 1.0 20.0)) base_y) (- (- (/ 1.0 20.0)) base_y))) ?x440)))))))
(assert
 (let ((?x440 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x432 (- 1.0 base_x)))
 (let ((?x436 (* ?x432 ?x432)))
 (let (($x443 (and |trajectory[0]|)))
 (=> $x443 (<= (+ ?x436 (* (- (- (/ 1.0 40.0)) base_y) (- (- (/ 1.0 40.0)) base_y))) ?x440)))))))
(assert
 (let ((?x440 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x432 (- 1.0 base_x)))
 (let ((?x436 (* ?x432 ?x432)))
 (let (($x443 (and |trajectory[0]|)))
 (=> $x443 (<= (+ ?x436 (* (- 0.0 base_y) (- 0.0 base_y))) ?x440)))))))
(assert
 (let ((?x440 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x432 (- 1.0 base_x)))
 (let ((?x436 (* ?x432 ?x432)))
 (let (($x443 (and |trajectory[0]|)))
 (=> $x443 (<= (+ ?x436 (* (- (/ 1.0 40.0) base_y) (- (/ 1.0 40.0) base_y))) ?x440)))))))
(assert
 (let ((?x440 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x432 (- 1.0 base_x)))
 (let ((?x436 (* ?x432 ?x432)))
 (let (($x443 (and |trajectory[0]|)))
 (=> $x443 (<= (+ ?x436 (* (- (/ 1.0 20.0) base_y) (- (/ 1.0 20.0) base_y))) ?x440)))))))
(assert
 (let ((?x440 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x432 (- 1.0 base_x)))
 (let ((?x436 (* ?x432 ?x432)))
 (let (($x443 (and |trajectory[0]|)))
 (=> $x443 (<= (+ ?x436 (* (- (/ 3.0 40.0) base_y) (- (/ 3.0 40.0) base_y))) ?x440)))))))
(assert
 (let ((?x440 (+ (* reach reach) (/ 1.0 10000000.0))))
 (let ((?x432 (- 1.0 base_x)))
 (let ((?x436 (* ?x432 ?x432)))
 (let (($x443 (and |trajectory[0]|)))
 (=> $x443 (<= (+ ?x436 (* (- (/ 1.0 10.0) base_y) (- (/ 1.0 10.0) base_y))) ?x440)))))))
(assert
 (let (($x443 (and |trajectory[0]|)))
 (=> $x443 (>= (* 2.0 reach) (/ 1999999.0 10000000.0)))))
(check-sat-assuming (|robot.min_link_length| |robot.max_link_length| |robot.link_diameter| |base_regions| |obstacles[0]| |obstacles[1]| |obstacles[2]| |obstacles[3]| |obstacles[4]| |obstacles[5]| |obstacles[6]| |obstacles[7]| |obstacles[8]| |obstacles[9]| |obstacles[10]| |obstacles[11]| |obstacles[12]| |obstacles[13]| |obstacles[14]| |obstacles[15]| |obstacles[16]| |obstacles[17]| |obstacles[18]| |obstacles[19]| |obstacles[20]| |obstacles[21]| |obstacles[22]| |obstacles[23]| |obstacles[24]| |obstacles[25]| |obstacles[26]| |obstacles[27]| |obstacles[28]| |obstacles[29]| |obstacles[30]| |obstacles[31]| |obstacles[32]| |obstacles[33]| |obstacles[34]| |obstacles[35]| |obstacles[36]| |obstacles[37]| |obstacles[38]| |obstacles[39]| |obstacles[40]| |obstacles[41]| |obstacles[42]| |obstacles[43]| |obstacles[44]| |obstacles[45]| |trajectory[0]|))
