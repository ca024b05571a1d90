package org.kheperasim.sim.host.loading;

import java.util.Calendar;
import java.util.Date;
import java.util.GregorianCalendar;
import java.util.Locale;
import java.util.TimeZone;
import org.kheperasim.sim.host.SimClock;

/**
 * Where controller code's wall-clock reads of {@code java.util} go instead (see {@link CallTargets}):
 * {@code Calendar.getInstance(...)}, {@code new GregorianCalendar()} (each overload without a date)
 * and {@code new Date()} give the same calendar or date, set to the simulated clock, as
 * {@code System.currentTimeMillis()} reads it. The JDK reads the wall clock inside
 * {@code getInstance} and the constructors, where the rewrite of {@code currentTimeMillis} does not
 * reach, so the rewrite sets the object after the JDK made it ({@link #simulatedNow(Calendar)},
 * {@link #simulatedNow(Date)}), and a constructor reference ({@code GregorianCalendar::new}) goes to
 * the factories here.
 */
public final class CalendarHooks {
    private CalendarHooks() {
    }

    /** Replaces {@link Calendar#getInstance()}. */
    public static Calendar getInstance() {
        return now(Calendar.getInstance());
    }

    /** Replaces {@link Calendar#getInstance(TimeZone)}. */
    public static Calendar getInstance(TimeZone zone) {
        return now(Calendar.getInstance(zone));
    }

    /** Replaces {@link Calendar#getInstance(Locale)}. */
    public static Calendar getInstance(Locale locale) {
        return now(Calendar.getInstance(locale));
    }

    /** Replaces {@link Calendar#getInstance(TimeZone, Locale)}. */
    public static Calendar getInstance(TimeZone zone, Locale locale) {
        return now(Calendar.getInstance(zone, locale));
    }

    /** Replaces the constructor reference {@code GregorianCalendar::new} (no arguments). */
    public static GregorianCalendar newGregorianCalendar() {
        return now(new GregorianCalendar());
    }

    /** Replaces the constructor reference to {@link GregorianCalendar#GregorianCalendar(TimeZone)}. */
    public static GregorianCalendar newGregorianCalendar(TimeZone zone) {
        return now(new GregorianCalendar(zone));
    }

    /** Replaces the constructor reference to {@link GregorianCalendar#GregorianCalendar(Locale)}. */
    public static GregorianCalendar newGregorianCalendar(Locale locale) {
        return now(new GregorianCalendar(locale));
    }

    /** Replaces the constructor reference to {@link GregorianCalendar#GregorianCalendar(TimeZone, Locale)}. */
    public static GregorianCalendar newGregorianCalendar(TimeZone zone, Locale locale) {
        return now(new GregorianCalendar(zone, locale));
    }

    /** Replaces the constructor reference {@code Date::new} (no arguments). */
    public static Date newDate() {
        Date d = new Date();
        simulatedNow(d);
        return d;
    }

    /**
     * Called on a calendar just made by a wall-clock constructor ({@code new GregorianCalendar()}, or
     * the {@code super()} of a subclass's constructor): sets it to the simulated clock.
     */
    public static void simulatedNow(Calendar c) {
        c.setTimeInMillis(SimClock.currentTimeMillis());
    }

    /**
     * Called on a date just made by {@code new Date()} (or the {@code super()} of a subclass's
     * constructor): sets it to the simulated clock.
     */
    public static void simulatedNow(Date d) {
        d.setTime(SimClock.currentTimeMillis());
    }

    private static <C extends Calendar> C now(C c) {
        simulatedNow(c);
        return c;
    }
}
