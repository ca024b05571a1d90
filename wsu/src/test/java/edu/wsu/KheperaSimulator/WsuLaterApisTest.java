package edu.wsu.KheperaSimulator;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.api.MessagePasser;
import org.kheperasim.api.binding.Controllers;
import org.kheperasim.api.spi.TruePose;

/**
 * What later course code relies on, on a fake robot: {@code simStart()} in the life cycle, KSuite
 * 1.1.2's vision turret, a later fork's pose and the original's wheel counts.
 */
@Timeout(value = 20, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class WsuLaterApisTest {
    static final List<String> LOG = Collections.synchronizedList(new ArrayList<>());

    private final FakePort port = new FakePort();
    private final AtomicReference<Throwable> uncaught = new AtomicReference<>();

    private void runToEnd(Class<?> type) throws InterruptedException {
        LOG.clear();
        Thread t = Controllers.instantiate(type, new org.kheperasim.api.CurrentRobotState(port), new MessagePasser(port));
        t.setUncaughtExceptionHandler((thread, e) -> uncaught.set(e));
        t.start();
        t.join();
    }

    /** As 2012 course controllers start moving: speeds in simStart(); it also calls simStart() again. */
    public static class Starter extends RobotController {
        private int steps;

        public Starter() {
        }

        @Override
        public void simStart() {
            super.simStart();
            LOG.add("simStart on " + Thread.currentThread().getName());
            setMotorSpeeds(5, 5);
        }

        @Override
        public void doWork() {
            LOG.add("doWork on " + Thread.currentThread().getName());
            super.simStart();
            setMotorSpeeds(-5, 70);
            if (++steps == 2) {
                setFinished(true);
            }
        }

        @Override
        public void close() {
        }
    }

    @Test
    void simStartRunsOnceOnTheControllersThreadBeforeTheFirstDoWork() throws Exception {
        runToEnd(Starter.class);
        assertNull(uncaught.get());
        assertEquals(List.of("simStart on Starter", "doWork on Starter", "doWork on Starter"), LOG);
        assertEquals("5,5", port.speeds.get(0), "simStart's speeds come before any doWork");
        assertEquals("-5,5", port.speeds.get(1), "70 is ignored: the right wheel keeps simStart's 5");
    }

    /** A simStart() that throws. */
    public static class BadStart extends RobotController {
        public BadStart() {
        }

        @Override
        protected void simStart() {
            throw new IllegalStateException("no start");
        }

        @Override
        public void doWork() {
            LOG.add("doWork");
        }

        @Override
        public void close() {
            LOG.add("close");
        }
    }

    @Test
    void anExceptionFromSimStartEndsTheControllerAfterClose() throws Exception {
        runToEnd(BadStart.class);
        assertEquals("no start", uncaught.get().getMessage());
        assertEquals(List.of("close"), LOG);
        assertEquals("0,0", port.lastSpeeds());
    }

    /** Reads the turret and its extremes once. */
    public static class Looker extends RobotController {
        static volatile float[] image;
        static volatile float max;
        static volatile float min;

        public Looker() {
        }

        @Override
        public void doWork() {
            image = readLvtImage();
            max = getPixelMaxIntensity();
            min = getPixelMinIntensity();
            setFinished(true);
        }

        @Override
        public void close() {
        }
    }

    @Test
    void theVisionTurretGivesFloatsOfGreyLevelsAndTheBrightestAndDarkestLevels() throws Exception {
        int[] img = new int[64];
        java.util.Arrays.fill(img, 10);
        img[40] = 255;
        img[41] = 255;
        img[12] = 0;
        port.image = img;
        runToEnd(Looker.class);
        float[] expected = new float[64];
        for (int i = 0; i < 64; i++) {
            expected[i] = img[i];
        }
        assertArrayEquals(expected, Looker.image);
        assertEquals(255f, Looker.max, "the brightest grey level, as the original returned it (not the pixel's index)");
        assertEquals(0f, Looker.min, "the darkest grey level");
    }

    /** Reports the fork's pose, and the wheel positions. */
    public static class Where extends RobotController {
        static volatile float angle;
        static volatile int x;
        static volatile int y;
        static volatile long left;

        public Where() {
        }

        @Override
        public void doWork() {
            angle = getRobotAngle();
            x = getRobotXPosition();
            y = getRobotYPosition();
            left = getLeftWheelPosition();
            setFinished(true);
        }

        @Override
        public void close() {
        }
    }

    @Test
    void thePoseIsTheSimulatorsInTheOriginalsPanelUnits() throws Exception {
        // Centre at (263, 263) px of a 1219.2 mm arena, y up: 263 px from the top; heading 90 deg to the left.
        port.truth = new TruePose(263 * 2.4384, 1219.2 - 263 * 2.4384, 90, 1219.2, 1219.2);
        runToEnd(Where.class);
        assertEquals(263, Where.x);
        assertEquals(263, Where.y);
        assertEquals(3 * Math.PI / 2, Where.angle, 1e-5, "facing up the screen: clockwise 270 degrees");
        assertTrue(port.messages.isEmpty(), "no note in the simulator: " + port.messages);
    }

    @Test
    void onARealRobotThePoseIsOdometryFromTheStartSpotWithANote() {
        WsuPose pose = new WsuPose(port);
        pose.start(1000, 1000);
        // A quarter turn to the left on the spot (each wheel 26.5 mm x pi / 2), then 100 mm ahead.
        int quarter = (int) Math.round(26.5 * Math.PI / 2 / 0.08);
        port.leftPosition = 1000 - quarter;
        port.rightPosition = 1000 + quarter;
        assertEquals(3 * Math.PI / 2, pose.angle(), 0.01, "facing up the screen");
        port.leftPosition += 1250;
        port.rightPosition += 1250;
        assertEquals(263, pose.x());
        assertEquals(263 - 100 / 2.4384, pose.y(), 1, "100 mm up the screen");
        assertEquals(1, port.messages.stream().filter(m -> m.contains("odometry")).count(), "once: " + port.messages);
    }

    @Test
    void legacyPositionsCountThreeADegreeOfATurnOnTheSpot() {
        port.options.put("wsu.positionUnits", "legacy");
        // 90 degrees on the spot: each wheel travels 26.5 mm x pi / 2 = 41.6 mm = 520 pulses.
        CurrentRobotState s = new CurrentRobotState(port);
        s.startRun();
        port.leftPosition = (int) Math.round(26.5 * Math.PI / 2 / 0.08);
        assertEquals(270, s.getLeftPosition(), "3 counts a degree");
        port.options.put("wsu.positionUnits", "pulses");
        CurrentRobotState p = new CurrentRobotState(port);
        p.startRun();
        port.leftPosition += 100;
        assertEquals(100, p.getLeftPosition());
        port.options.put("wsu.positionUnits", "furlongs");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new CurrentRobotState(port));
        assertTrue(e.getMessage().contains("wsu.positionUnits=furlongs") && e.getMessage().contains("legacy"), e.getMessage());
    }
}
