t2_long_test(test_orient "Orient.*:Side.*" 1000)
t2_long_test(test_polygon "PolygonTyped*" 100)
t2_long_test(test_scene "Scene.EveryDouble*:Scene.Random*" 1000)
