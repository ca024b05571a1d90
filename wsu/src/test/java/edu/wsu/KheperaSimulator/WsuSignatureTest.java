package edu.wsu.KheperaSimulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * Binary compatibility with classes compiled against the original: exact names, parameter and
 * return types, access, and the constants' values (javac copies them into student classes).
 */
class WsuSignatureTest {

    private static void has(Class<?> type, int access, Class<?> returns, String name, Class<?>... parameters)
            throws NoSuchMethodException {
        Method m = type.getDeclaredMethod(name, parameters);
        assertEquals(returns, m.getReturnType(), name);
        assertTrue((m.getModifiers() & access) == access, name + " is " + Modifier.toString(m.getModifiers()));
    }

    @Test
    void robotControllerHasTheOriginalsMembers() throws Exception {
        Class<RobotController> rc = RobotController.class;
        assertTrue(Modifier.isPublic(rc.getModifiers()) && Modifier.isAbstract(rc.getModifiers()));
        assertTrue(Controller.class.isAssignableFrom(rc) && Runnable.class.isAssignableFrom(rc));
        assertTrue(Modifier.isPublic(rc.getConstructor().getModifiers()));
        int pub = Modifier.PUBLIC;
        int prot = Modifier.PROTECTED;
        has(rc, prot, void.class, "initialize", String.class, CurrentRobotState.class, long.class);
        has(rc, prot, void.class, "simStart");
        has(rc, prot, void.class, "setWaitTime", long.class);
        has(rc, prot, void.class, "setFinished", boolean.class);
        has(rc, prot, boolean.class, "isRunning");
        has(rc, pub, void.class, "run");
        has(rc, pub, void.class, "sleep", long.class);
        has(rc, pub, void.class, "setMotorSpeeds", int.class, int.class);
        has(rc, pub, void.class, "setLeftMotorSpeed", int.class);
        has(rc, pub, void.class, "setRightMotorSpeed", int.class);
        has(rc, pub, void.class, "setArmState", int.class);
        has(rc, pub, void.class, "setGripperState", int.class);
        has(rc, pub, int.class, "getArmState");
        has(rc, pub, int.class, "getGripperState");
        has(rc, pub, boolean.class, "isObjectPresent");
        has(rc, pub, boolean.class, "isObjectHeld");
        has(rc, pub, int.class, "getLightValue", int.class);
        has(rc, pub, int.class, "getDistanceValue", int.class);
        has(rc, pub, int.class, "getResistivity");
        has(rc, pub, long.class, "getLeftWheelPosition");
        has(rc, pub, long.class, "getRightWheelPosition");
        // KSuite 1.1.2's K213 vision turret, and a later fork's pose (descriptors as course classes call them).
        has(rc, pub, float[].class, "readLvtImage");
        has(rc, pub, float.class, "getPixelMaxIntensity");
        has(rc, pub, float.class, "getPixelMinIntensity");
        has(rc, pub, float.class, "getRobotAngle");
        has(rc, pub, int.class, "getRobotXPosition");
        has(rc, pub, int.class, "getRobotYPosition");
    }

    @Test
    void theControllerInterfaceAndTheStateAreTheOriginals() throws Exception {
        assertTrue(Controller.class.isInterface() && Runnable.class.isAssignableFrom(Controller.class));
        assertEquals(2, Controller.class.getDeclaredMethods().length);
        Method doWork = Controller.class.getMethod("doWork");
        Method close = Controller.class.getMethod("close");
        assertEquals(Exception.class, doWork.getExceptionTypes()[0]);
        assertEquals(Exception.class, close.getExceptionTypes()[0]);

        Class<CurrentRobotState> s = CurrentRobotState.class;
        assertTrue(Modifier.isPublic(s.getConstructor().getModifiers()));
        has(s, Modifier.PUBLIC, void.class, "setMotorSpeeds", int.class, int.class);
        has(s, Modifier.PUBLIC, void.class, "setLeftMotorSpeed", int.class);
        has(s, Modifier.PUBLIC, void.class, "setRightMotorSpeed", int.class);
        has(s, Modifier.PUBLIC, long.class, "getLeftPosition");
        has(s, Modifier.PUBLIC, long.class, "getRightPosition");
        for (Method m : s.getDeclaredMethods()) {
            if (Modifier.isPublic(m.getModifiers())) {
                assertTrue(m.getName().matches("set(Left|Right)?MotorSpeeds?|get(Left|Right)Position"),
                        "no public member beyond the original's: " + m);
            }
        }
    }

    @Test
    void gripperStatesAreTheOriginalsConstants() throws Exception {
        Map<String, Integer> expected = Map.of("ARM_UP", 20, "ARM_DOWN", 21, "GRIP_OPEN", 22, "GRIP_CLOSED", 23);
        for (Map.Entry<String, Integer> e : expected.entrySet()) {
            Field f = KSGripperStates.class.getField(e.getKey());
            int m = f.getModifiers();
            assertTrue(Modifier.isPublic(m) && Modifier.isStatic(m) && Modifier.isFinal(m), e.getKey());
            assertEquals(int.class, f.getType());
            assertEquals(e.getValue(), f.get(null));
        }
        assertEquals(20, KSGripperStates.ARM_UP);
        assertEquals(23, KSGripperStates.GRIP_CLOSED);
    }

    @Test
    void robotControllerAddsNoPublicOrProtectedMemberAStudentsMethodCouldClashWith() {
        java.util.Set<String> original = java.util.Set.of("initialize", "simStart", "setWaitTime", "setFinished",
                "isRunning", "run", "sleep", "setMotorSpeeds", "setLeftMotorSpeed", "setRightMotorSpeed", "setArmState",
                "setGripperState", "getArmState", "getGripperState", "isObjectPresent", "isObjectHeld", "getLightValue",
                "getDistanceValue", "getResistivity", "getLeftWheelPosition", "getRightWheelPosition",
                "readLvtImage", "getPixelMaxIntensity", "getPixelMinIntensity", "getRobotAngle", "getRobotXPosition",
                "getRobotYPosition");
        for (Method m : RobotController.class.getDeclaredMethods()) {
            int mod = m.getModifiers();
            if ((Modifier.isPublic(mod) || Modifier.isProtected(mod)) && !m.isSynthetic()) {
                assertTrue(original.contains(m.getName()), "extra visible member: " + m);
            }
        }
    }
}
