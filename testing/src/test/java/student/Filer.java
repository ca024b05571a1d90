package student;

import org.kheperasim.api.Controller;

/** Deletes a file: the simulator refuses to load a controller that touches files. */
public class Filer extends Controller {
    @Override
    protected void doWork() {
        sleepMillis(100);
        new java.io.File("results.txt").delete(); // touches a file here
    }
}
