cube();
