package org.kheperasim.testfixtures.loading;

/**
 * A controller compiled with the tests: it sits on the simulator's own classpath, like the bundled
 * demo controllers, so the controller class loader finds it as a resource of its parent.
 */
public class BundledSleeper extends Thread {
    @Override
    public void run() {
        try {
            sleep(100);
        } catch (InterruptedException e) {
            interrupt();
        }
    }
}
