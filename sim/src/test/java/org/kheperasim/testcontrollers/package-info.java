/**
 * Controllers used by the simulator's tests. They live outside {@code org.kheperasim.sim} so that
 * the controller class loader rewrites them exactly as it rewrites a student's classes.
 */
package org.kheperasim.testcontrollers;
