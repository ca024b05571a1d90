/**
 * The Khepera I/II ASCII protocol as pure string code (no I/O): a typed {@link
 * org.kheperasim.link.protocol.Command} for each of the 18 commands and the gripper turret's
 * commands, encoding and parsing of command lines (for a client and for a server that answers
 * like a robot), and reply formatting and parsing that recognises the robot's error replies.
 */
package org.kheperasim.link.protocol;
