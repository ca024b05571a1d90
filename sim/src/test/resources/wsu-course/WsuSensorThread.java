import edu.wsu.KheperaSimulator.RobotController;

/**
 * A sensor manager in its own thread, started in the constructor: it keeps the latest front
 * reading in a synchronized field; doWork steers from it. The thread ends with the controller.
 */
public class WsuSensorThread extends RobotController {
    private int front;
    private int reads;

    public WsuSensorThread() {
        Thread manager = new Thread(new Runnable() {
            public void run() {
                while (true) {
                    update();
                    try {
                        Thread.sleep(30);
                    } catch (InterruptedException e) {
                        return;
                    }
                }
            }
        }, "sensor-manager");
        manager.start();
    }

    private synchronized void update() {
        front = Math.max(getDistanceValue(2), getDistanceValue(3));
        reads++;
    }

    private synchronized int front() {
        return front;
    }

    public void doWork() throws Exception {
        if (front() > 400) {
            setMotorSpeeds(4, -4);
        } else {
            setMotorSpeeds(5, 5);
        }
        if (reads == 100) {
            System.out.println("100 reads at " + System.currentTimeMillis() % 100000);
        }
    }

    public void close() throws Exception {
        setMotorSpeeds(0, 0);
    }
}
