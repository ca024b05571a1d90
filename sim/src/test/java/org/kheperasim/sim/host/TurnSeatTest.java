package org.kheperasim.sim.host;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * {@link Turn.Seat}'s way in and out of the simulator's code against the watchdog's take: inside, the
 * turn is never taken; a take is never undone by the way out of a call that found itself taken; and
 * when the way in and the take race, exactly one of them wins.
 */
class TurnSeatTest {
    @Test
    void insideTheSimulatorTheTurnIsNeverTaken() {
        Turn.Seat me = new Turn.Seat(Thread.currentThread());
        Turn.Seat owner = new Turn.Seat(Thread.currentThread());
        Turn turn = new Turn(me);
        assertEquals(Turn.STUDENT, me.enterSimulator());
        assertEquals(Turn.SIMULATOR, me.enterSimulator(), "a nested entry stays inside");
        me.leaveSimulator(Turn.SIMULATOR);
        assertTrue(me.inSimulator(), "leaving a nested entry stays inside");
        assertFalse(turn.takeFromStuck(me, owner));
        me.leaveSimulator(Turn.STUDENT);
        assertFalse(me.inSimulator());
        assertTrue(turn.takeFromStuck(me, owner), "back in its own code, it may be taken");
        assertTrue(turn.heldBy(owner));
    }

    /** A call that finds itself taken throws, and its way out (leave) must leave it taken. */
    @Test
    void theWayOutOfACallThatFoundItselfTakenLeavesItTaken() {
        Turn.Seat me = new Turn.Seat(Thread.currentThread());
        Turn turn = new Turn(me);
        assertTrue(turn.takeFromStuck(me, new Turn.Seat(Thread.currentThread())));
        assertEquals(Turn.TAKEN, me.enterSimulator());
        me.leaveSimulator(Turn.STUDENT);
        assertTrue(me.taken(), "the take stands");
        assertEquals(Turn.TAKEN, me.enterSimulator(), "and it never enters again");
    }

    @Test
    @Timeout(60)
    void theWayInAndTheTakeNeverBothWin() throws Exception {
        int rounds = 2_000;
        AtomicInteger both = new AtomicInteger();
        AtomicInteger entered = new AtomicInteger();
        for (int i = 0; i < rounds; i++) {
            Turn.Seat seat = new Turn.Seat(Thread.currentThread());
            Turn turn = new Turn(seat);
            CyclicBarrier go = new CyclicBarrier(2);
            boolean[] in = new boolean[1];
            Thread student = new Thread(() -> {
                await(go);
                in[0] = seat.enterSimulator() == Turn.STUDENT;
            });
            student.start();
            await(go);
            boolean taken = turn.takeFromStuck(seat, new Turn.Seat(Thread.currentThread()));
            student.join();
            if (in[0]) {
                entered.incrementAndGet();
            }
            if (in[0] == taken) {
                both.incrementAndGet();
            }
        }
        assertEquals(0, both.get(), "rounds where both or neither won (of " + rounds + ", entered first " + entered + ")");
    }

    private static void await(CyclicBarrier b) {
        try {
            b.await();
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }
}
