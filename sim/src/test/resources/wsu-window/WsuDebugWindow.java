import edu.wsu.KheperaSimulator.RobotController;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.SwingUtilities;

/** A WSU controller with its own debug window, as students wrote them: it shows the front sensors. */
public class WsuDebugWindow extends RobotController {
    private JFrame frame;
    private JLabel label;

    public WsuDebugWindow() {
    }

    public void doWork() throws Exception {
        if (frame == null) {
            frame = new JFrame("WSU debug");
            label = new JLabel("front: -");
            label.setName("wsu-debug-label");
            frame.add(label);
            frame.setSize(260, 80);
            frame.setLocation(20, 20);
            frame.setVisible(true);
        }
        final int front = Math.max(getDistanceValue(2), getDistanceValue(3));
        SwingUtilities.invokeLater(new Runnable() {
            public void run() {
                label.setText("front: " + front);
            }
        });
        if (front > 400) {
            setMotorSpeeds(3, -3);
        } else {
            setMotorSpeeds(5, 5);
        }
        sleep(50);
    }

    public void close() throws Exception {
        setMotorSpeeds(0, 0);
    }
}
