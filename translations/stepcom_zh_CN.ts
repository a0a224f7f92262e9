<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>GivenFile</name>
    <message>
        <source>%1: no such file</source>
        <translation>%1：文件不存在</translation>
    </message>
    <message>
        <source>%1 is a folder, not a file</source>
        <translation>%1 是文件夹，不是文件</translation>
    </message>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 is neither a StepCom profile, a sequence, a session log nor a support bundle: StepCom opens those.</source>
        <translation>%1 既不是 StepCom 参数文件、序列、会话日志，也不是支持包：StepCom 只打开这些文件。</translation>
    </message>
</context>
<context>
    <name>stepcom</name>
    <message>
        <source>Commissioning window for a 2-axis stepper controller (Modbus RTU/TCP).</source>
        <translation>两轴步进电机控制器调试窗口（Modbus RTU/TCP）。</translation>
    </message>
    <message>
        <source>Start connected to the built-in simulator.</source>
        <translation>启动后连接内置仿真器。</translation>
    </message>
    <message>
        <source>Connect to this serial port at start.</source>
        <translation>启动时连接此串口。</translation>
    </message>
    <message>
        <source>path</source>
        <translation>路径</translation>
    </message>
    <message>
        <source>Connect to this Modbus TCP gateway at start.</source>
        <translation>启动时连接此 Modbus TCP 网关。</translation>
    </message>
    <message>
        <source>host:port</source>
        <translation>主机:端口</translation>
    </message>
    <message>
        <source>Baud rate (default 9600).</source>
        <translation>波特率（默认 9600）。</translation>
    </message>
    <message>
        <source>rate</source>
        <translation>波特率</translation>
    </message>
    <message>
        <source>Device id (default 1).</source>
        <translation>设备 ID（默认 1）。</translation>
    </message>
    <message>
        <source>id</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Connect at start to this RS-485/Ethernet converter in transparent mode (RTU over TCP).</source>
        <translation>启动时通过这个透明传输模式的 RS-485/以太网转换器连接（RTU over TCP）。</translation>
    </message>
    <message>
        <source>The adapter echoes what it sends.</source>
        <translation>适配器会回显发送的数据。</translation>
    </message>
    <message>
        <source>Parity: none, even or odd (default none).</source>
        <translation>校验位：none、even 或 odd（默认 none）。</translation>
    </message>
    <message>
        <source>parity</source>
        <translation>校验位</translation>
    </message>
    <message>
        <source>A profile to edit without a controller, or a session log or support bundle to replay.</source>
        <translation>要在不连接控制器时编辑的参数文件，或要回放的会话日志或支持包。</translation>
    </message>
    <message>
        <source>Start the built-in simulator from the factory again: forget what it saved to flash.</source>
        <translation>让内置仿真器恢复出厂状态：清除它保存到闪存的内容。</translation>
    </message>
    <message>
        <source>Start the phone pendant at launch (watch only) on this port, 0 for any free one; prints its address.</source>
        <translation>启动时在此端口启动手机手持器（仅监视），0 表示任一空闲端口；并打印其地址。</translation>
    </message>
    <message>
        <source>[address:]port</source>
        <translation>[地址:]端口</translation>
    </message>
    <message>
        <source>Allow jogging from the pendant from launch.</source>
        <translation>启动时即允许从手持器点动。</translation>
    </message>
    <message>
        <source>With --port: listen only, another master drives the line (nothing is sent but the E-STOP).</source>
        <translation>与 --port 一起使用：仅监听，由另一个主站驱动线路（除急停外不发送任何数据）。</translation>
    </message>
    <message>
        <source>--listen needs --port</source>
        <translation>--listen 需要 --port</translation>
    </message>
    <message>
        <source>With --sim: the simulated machine&apos;s mechanics from this machine file (stalls, backlash, switches; default: the setting simulator/machineFile).</source>
        <translation>与 --sim 一起使用：从此机器文件读取仿真机器的机械特性（失步、反向间隙、开关；默认：设置项 simulator/machineFile）。</translation>
    </message>
    <message>
        <source>file</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>%1 is above pull_out_rpm (%2): a motor cannot start faster than it runs</source>
        <translation>%1 高于 pull_out_rpm（%2）：电机的启动速度不可能高于运行速度</translation>
    </message>
    <message>
        <source>%1 is not above negative_switch_mm (%2)</source>
        <translation>%1 不大于 negative_switch_mm（%2）</translation>
    </message>
    <message>
        <source>%1 is beyond the hard stops</source>
        <translation>%1 超出了机械硬限位</translation>
    </message>
</context>
<context>
    <name>stepcom-sim</name>
    <message>
        <source>A simulated 2-axis stepper controller speaking Modbus RTU on a pseudo-terminal and/or Modbus TCP. Without --pty or --tcp it serves a pseudo-terminal.</source>
        <translation>模拟的两轴步进电机控制器，在伪终端上提供 Modbus RTU，和/或提供 Modbus TCP。未指定 --pty 或 --tcp 时使用伪终端。</translation>
    </message>
    <message>
        <source>Read console commands from standard input even when it is not a terminal.</source>
        <translation>即使标准输入不是终端，也从中读取控制台命令。</translation>
    </message>
    <message>
        <source>stepcom-sim: %1</source>
        <translation>stepcom-sim：%1</translation>
    </message>
    <message>
        <source>port hung up</source>
        <translation>端口已挂断</translation>
    </message>
    <message>
        <source>port back: %1</source>
        <translation>端口已恢复：%1</translation>
    </message>
    <message>
        <source>stepcom-sim %1: device id %2, %3 baud, %4 motors</source>
        <translation>stepcom-sim %1：设备 ID %2，波特率 %3，%4 个电机</translation>
    </message>
    <message>
        <source>type &apos;help&apos; for the console commands</source>
        <translation>输入 &apos;help&apos; 查看控制台命令</translation>
    </message>
    <message>
        <source>%1 controllers on the line, ids %2 (the console acts on the first)</source>
        <translation>总线上有 %1 台控制器，ID 为 %2（控制台操作第一台）</translation>
    </message>
    <message>
        <source>line %1 sent %2 bytes</source>
        <translation>线路端口 %1 发送了 %2 字节</translation>
    </message>
</context>
<context>
    <name>stepcom::AboutBox</name>
    <message>
        <source>About this page</source>
        <translation>关于本页</translation>
    </message>
    <message>
        <source>Show or hide what this page is for (F1: the user guide)</source>
        <translation>显示或隐藏本页的用途说明（F1：用户指南）</translation>
    </message>
    <message>
        <source>More in the user guide (F1)</source>
        <translation>用户指南中的详细说明（F1）</translation>
    </message>
</context>
<context>
    <name>stepcom::AnswerCheck</name>
    <message>
        <source>function %1 answered a request of function %2</source>
        <translation>功能码 %1 的应答对应的是功能码 %2 的请求</translation>
    </message>
    <message>
        <source>exception answer of %1 bytes</source>
        <translation>%1 字节的异常应答</translation>
    </message>
    <message>
        <source>FC03 answer carried %1 registers, %2 were asked for</source>
        <translation>FC03 应答带有 %1 个寄存器，请求的是 %2 个</translation>
    </message>
    <message>
        <source>FC%1 answer for 0x%2 = 0x%3, the request wrote 0x%4 = 0x%5</source>
        <translation>FC%1 应答为 0x%2 = 0x%3，请求写的是 0x%4 = 0x%5</translation>
    </message>
    <message>
        <source>FC10 answer for %1 registers at 0x%2, the request wrote %3 at 0x%4</source>
        <translation>FC10 应答为 0x%2 处 %1 个寄存器，请求在 0x%4 处写了 %3 个</translation>
    </message>
</context>
<context>
    <name>stepcom::ApplyToDevicesDialog</name>
    <message>
        <source>&amp;Compare the ticked devices</source>
        <translation>比较勾选的设备(&amp;C)</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Apply %1 to several devices</source>
        <translation>将 %1 应用到多台设备</translation>
    </message>
    <message>
        <source>Tick the devices, compare, then uncheck what is not to be written. Each device&apos;s settings are saved as a backup before anything is written to it; every value written is read back. Device id and baud rate are never applied to several devices: one id for all would make them collide.</source>
        <translation>勾选设备并比较，然后取消不想写入的行。写入任何数据之前，先把每台设备的设置保存为备份；写入的每个值都会读回校验。设备 ID 和波特率从不同时写入多台设备：所有设备同一个 ID 会造成冲突。</translation>
    </message>
    <message>
        <source>id %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>id %1 (%2)</source>
        <translation>ID %1（%2）</translation>
    </message>
    <message>
        <source>Device / parameter</source>
        <translation>设备 / 参数</translation>
    </message>
    <message>
        <source>Device holds</source>
        <translation>设备中的值</translation>
    </message>
    <message>
        <source>Profile</source>
        <translation>参数文件</translation>
    </message>
    <message>
        <source>Done:</source>
        <translation>完成：</translation>
    </message>
    <message>
        <source>Done, not everywhere:</source>
        <translation>完成，但并非全部成功：</translation>
    </message>
    <message numerus="yes">
        <source>Reading %n device(s)…</source>
        <translation>
            <numerusform>正在读取 %n 台设备…</numerusform>
        </translation>
    </message>
    <message>
        <source>Nothing has been written yet.</source>
        <translation>尚未写入任何数据。</translation>
    </message>
    <message>
        <source>Nothing to write: the devices hold the profile&apos;s values or could not be read.</source>
        <translation>没有需要写入的：设备已与参数文件一致，或无法读取。</translation>
    </message>
    <message>
        <source>Writing…</source>
        <translation>正在写入…</translation>
    </message>
    <message>
        <source>Writing… this window stays open until every device has its result. E-STOP (F12) stops what is left.</source>
        <translation>正在写入…在每台设备都有结果之前此窗口保持打开。急停（F12）会停止剩下的操作。</translation>
    </message>
    <message numerus="yes">
        <source>&amp;Write %n value(s) to %1 device(s)</source>
        <translation>
            <numerusform>向 %1 台设备写入 %n 个值(&amp;W)</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Write</source>
        <translation>写入(&amp;W)</translation>
    </message>
</context>
<context>
    <name>stepcom::AxisProof</name>
    <message>
        <source>Motor %1: reading its values</source>
        <translation>电机 %1：正在读取其参数</translation>
    </message>
    <message>
        <source>cycles must be 1 to 1000, not %1</source>
        <translation>循环次数必须在 1 到 1000 之间，不能是 %1</translation>
    </message>
    <message>
        <source>the distance must be above 0 and within the single move&apos;s range, not %1</source>
        <translation>距离必须大于 0 且在单次运行的范围内，不能是 %1</translation>
    </message>
    <message>
        <source>Motor %1: the test speed %2 rpm: %3</source>
        <translation>电机 %1：测试转速 %2 rpm：%3</translation>
    </message>
    <message>
        <source>Motor %1: the test acceleration %2: %3</source>
        <translation>电机 %1：测试加速度 %2：%3</translation>
    </message>
    <message>
        <source>The test needs the travel from the home switch to %1 %2 past it: %3</source>
        <translation>测试需要从原点开关到越过它 %1 %2 处的行程：%3</translation>
    </message>
    <message>
        <source>Motor %1 stands at its lower travel limit: the home switch beyond it cannot be searched for</source>
        <translation>电机 %1 位于行程限位的下限：无法越过它寻找原点开关</translation>
    </message>
    <message>
        <source>Motor %1: the lost-step test</source>
        <translation>电机 %1：丢步测试</translation>
    </message>
    <message>
        <source>  reference: the home switch on IN%1, approached in the negative direction (up to %2 %3) at %4 rpm, %5</source>
        <translation>  参考：IN%1 上的原点开关，以 %4 rpm 从负方向趋近（最多 %2 %3），%5</translation>
    </message>
    <message>
        <source>from where the last test found it</source>
        <translation>从上次测试找到它的位置开始</translation>
    </message>
    <message>
        <source>twice, to measure its repeatability</source>
        <translation>共两次，以测量其重复性</translation>
    </message>
    <message>
        <source>  then %1 cycle(s) of %2 %3 out at %4 rpm (acceleration %5 %6) and back at %7 rpm, a reference, the same out at %7 rpm and back at %4 rpm, a reference</source>
        <translation>  然后 %1 个循环：每次以 %4 rpm（加速度 %5 %6）外移 %2 %3、以 %7 rpm 返回，参考一次；再以 %7 rpm 外移、以 %4 rpm 返回同样的距离，参考一次</translation>
    </message>
    <message>
        <source>  travel: from the home switch to %1 %2 past it</source>
        <translation>  行程：从原点开关到越过它 %1 %2 处</translation>
    </message>
    <message>
        <source>  afterwards: speed %1 rpm and acceleration %2 %3 put back and verified</source>
        <translation>  之后：恢复速度 %1 rpm 和加速度 %2 %3 并校验</translation>
    </message>
    <message>
        <source>Motor %1: reference 1 of 2 on the home switch</source>
        <translation>电机 %1：在原点开关上参考（第 1 次，共 2 次）</translation>
    </message>
    <message>
        <source>Motor %1: reference 2 of 2 on the home switch</source>
        <translation>电机 %1：在原点开关上参考（第 2 次，共 2 次）</translation>
    </message>
    <message>
        <source>Motor %1: the reference on the home switch failed: %2</source>
        <translation>电机 %1：在原点开关上参考失败：%2</translation>
    </message>
    <message>
        <source>Motor %1: %2 cycle(s) out at %3 rpm, back at %4 rpm</source>
        <translation>电机 %1：%2 个循环，以 %3 rpm 外移，以 %4 rpm 返回</translation>
    </message>
    <message>
        <source>Motor %1: reference on the home switch</source>
        <translation>电机 %1：在原点开关上参考</translation>
    </message>
    <message>
        <source>Stopped before anything moved</source>
        <translation>在任何运动之前已停止</translation>
    </message>
    <message>
        <source>Motor %1 %2 at %3 rpm: %4 %5 off after the moves out, %6 %5 after the moves back (switch repeatability %7 %5, 4 full steps %8 %5)</source>
        <translation>电机 %1 在 %3 rpm 下%2：外移后偏差 %4 %5，返回后偏差 %6 %5（开关重复性 %7 %5，4 个整步为 %8 %5）</translation>
    </message>
    <message>
        <source>The switch did not repeat well enough to tell a loss of 4 full steps.</source>
        <translation>开关的重复性不足以分辨 4 个整步的丢步。</translation>
    </message>
</context>
<context>
    <name>stepcom::BacklashTest</name>
    <message>
        <source>cycles must be 1 to 100, not %1</source>
        <translation>循环次数必须在 1 到 100 之间，不能是 %1</translation>
    </message>
    <message>
        <source>the distance must be above 0 and within the single move&apos;s range, not %1</source>
        <translation>距离必须大于 0 且在单次运行的范围内，不能是 %1</translation>
    </message>
    <message>
        <source>The test moves %1 %2 either way: %3</source>
        <translation>测试向两个方向各移动 %1 %2：%3</translation>
    </message>
    <message>
        <source>Motor %1: the backlash test with a dial gauge on the carriage</source>
        <translation>电机 %1：反向间隙测试（百分表装在滑台上）</translation>
    </message>
    <message>
        <source>  back %1 %2 and on %1 %2 (the approach), then %3 time(s) on %1 %2 and back %1 %2, at %4 rpm; the gauge is read %5 times</source>
        <translation>  先退回 %1 %2 再前进 %1 %2（趋近移动），然后 %3 次前进 %1 %2、退回 %1 %2，转速 %4 rpm；共读取百分表 %5 次</translation>
    </message>
    <message>
        <source>  afterwards: speed %1 rpm put back and verified</source>
        <translation>  之后：恢复速度 %1 rpm 并校验</translation>
    </message>
    <message>
        <source>Motor %1: the approach</source>
        <translation>电机 %1：趋近移动</translation>
    </message>
    <message>
        <source>after the approach</source>
        <translation>趋近移动之后</translation>
    </message>
    <message>
        <source>Motor %1: backlash %2 %3 (spread %4 %3 over %5 reversals)</source>
        <translation>电机 %1：反向间隙 %2 %3（%5 次反向的极差 %4 %3）</translation>
    </message>
    <message>
        <source>It is more than the count&apos;s resolution: position the axis from one side (approach every point in the same direction)</source>
        <translation>它大于计数分辨率：请从同一侧定位该轴（每个位置都从同一方向趋近）</translation>
    </message>
    <message>
        <source>Motor %1: move %2 of %3</source>
        <translation>电机 %1：第 %2 次移动（共 %3 次）</translation>
    </message>
    <message>
        <source>after moving on by %1</source>
        <translation>前进 %1 之后</translation>
    </message>
    <message>
        <source>after moving back by %1</source>
        <translation>退回 %1 之后</translation>
    </message>
    <message>
        <source>Stopped: no more readings</source>
        <translation>已停止：没有更多读数</translation>
    </message>
</context>
<context>
    <name>stepcom::BackupGuard</name>
    <message>
        <source>No backup of the controller&apos;s settings could be saved (%1): %2 was not done</source>
        <translation>无法保存控制器参数的备份（%1）：未执行%2</translation>
    </message>
    <message>
        <source>Backup of the controller&apos;s settings before %1: %2</source>
        <translation>%1前已备份控制器参数：%2</translation>
    </message>
</context>
<context>
    <name>stepcom::BackupStore</name>
    <message>
        <source>apply a profile</source>
        <translation>应用参数文件</translation>
    </message>
    <message>
        <source>factory reset</source>
        <translation>恢复出厂参数</translation>
    </message>
    <message>
        <source>save to flash</source>
        <translation>保存到闪存</translation>
    </message>
    <message>
        <source>device id change</source>
        <translation>修改设备地址</translation>
    </message>
    <message>
        <source>baud rate change</source>
        <translation>修改波特率</translation>
    </message>
    <message>
        <source>cannot create the backup folder %1</source>
        <translation>无法创建备份文件夹 %1</translation>
    </message>
    <message>
        <source>no settings to back up: the controller was not read</source>
        <translation>没有可备份的设置：未读取控制器</translation>
    </message>
    <message>
        <source>Backup before %1</source>
        <translation>%1前的备份</translation>
    </message>
</context>
<context>
    <name>stepcom::BackupsDialog</name>
    <message>
        <source>cannot be read: %1</source>
        <translation>无法读取：%1</translation>
    </message>
    <message>
        <source>Backups</source>
        <translation>备份</translation>
    </message>
    <message>
        <source>StepCom saves the controller&apos;s settings here before every apply, factory reset, save to flash and id or baud change: %1</source>
        <translation>每次应用参数文件、恢复出厂参数、保存到闪存以及修改设备地址或波特率之前，StepCom 都会把控制器参数保存在这里：%1</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>设备</translation>
    </message>
    <message>
        <source>What happened after</source>
        <translation>之后进行的操作</translation>
    </message>
    <message>
        <source>Restore…</source>
        <translation>恢复…</translation>
    </message>
    <message>
        <source>Compare the backup with the controller and apply what you check</source>
        <translation>将备份与控制器比较，并应用勾选的项</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
</context>
<context>
    <name>stepcom::BuiltinSimulator</name>
    <message>
        <source>cannot remove %1: %2</source>
        <translation>无法删除 %1：%2</translation>
    </message>
    <message>
        <source>cannot make the folder of %1</source>
        <translation>无法创建 %1 所在的文件夹</translation>
    </message>
    <message>
        <source>%1 (the simulator runs as the ideal machine)</source>
        <translation>%1（仿真器按理想机器运行）</translation>
    </message>
</context>
<context>
    <name>stepcom::BusActions</name>
    <message>
        <source>Assign device ids…</source>
        <translation>分配设备 ID…</translation>
    </message>
    <message>
        <source>Give each controller of a new line its own id, one controller at a time</source>
        <translation>为新总线上的每台控制器逐台分配各自的 ID</translation>
    </message>
    <message>
        <source>the built-in simulator is reset to the factory</source>
        <translation>内置仿真器已恢复出厂状态</translation>
    </message>
    <message>
        <source>The built-in simulator could not be reset: %1</source>
        <translation>无法重置内置仿真器：%1</translation>
    </message>
    <message>
        <source>The built-in simulator is back at the factory: id 1, 9600 baud, nothing saved. Connect to it again to start it.</source>
        <translation>内置仿真器已恢复出厂状态：ID 1，9600 波特，未保存任何内容。重新连接即可启动它。</translation>
    </message>
    <message>
        <source>Reset the built-in simulator to factory</source>
        <translation>将内置仿真器恢复出厂状态</translation>
    </message>
    <message>
        <source>Forget what the built-in simulator saved to flash: it starts again as it leaves the factory</source>
        <translation>清除内置仿真器保存到闪存的内容：它将以出厂状态重新启动</translation>
    </message>
</context>
<context>
    <name>stepcom::BusDump</name>
    <message>
        <source>%1: no such folder</source>
        <translation>%1：文件夹不存在</translation>
    </message>
    <message>
        <source>%1 is not a folder</source>
        <translation>%1 不是文件夹</translation>
    </message>
    <message>
        <source>%1: the folder cannot be written to</source>
        <translation>%1：无法写入该文件夹</translation>
    </message>
    <message>
        <source>Controller id %1</source>
        <translation>控制器 ID %1</translation>
    </message>
</context>
<context>
    <name>stepcom::BusScanDialog</name>
    <message>
        <source>Scan bus</source>
        <translation>扫描总线</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>扫描位置</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>端口：</translation>
    </message>
    <message>
        <source>What to try</source>
        <translation>扫描范围</translation>
    </message>
    <message>
        <source>&amp;Baud rates:</source>
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <source>Try this baud rate (register 40213; the factory setting is 9600)</source>
        <translation>尝试此波特率（寄存器 40213；出厂设置为 9600）</translation>
    </message>
    <message>
        <source>Device &amp;ids:</source>
        <translation>设备 ID(&amp;I)：</translation>
    </message>
    <message>
        <source>to</source>
        <translation>至</translation>
    </message>
    <message>
        <source>First device id to try (register 40212; factory setting 1)</source>
        <translation>要尝试的起始设备 ID（寄存器 40212；出厂设置为 1）</translation>
    </message>
    <message>
        <source>Last device id to try; 247 is the highest standard Modbus address</source>
        <translation>要尝试的结束设备 ID；247 是 Modbus 标准规定的最大地址</translation>
    </message>
    <message>
        <source>Probe &amp;timeout:</source>
        <translation>探测超时(&amp;T)：</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Stop at the &amp;first controller found</source>
        <translation>找到第一个控制器即停止(&amp;F)</translation>
    </message>
    <message>
        <source>Finish as soon as one controller answers</source>
        <translation>只要有一个控制器应答就结束扫描</translation>
    </message>
    <message>
        <source>&amp;Start</source>
        <translation>开始(&amp;S)</translation>
    </message>
    <message>
        <source>Start the scan; it only reads, nothing is written</source>
        <translation>开始扫描；只读取，不写入任何数据</translation>
    </message>
    <message>
        <source>&amp;Cancel</source>
        <translation>取消(&amp;C)</translation>
    </message>
    <message>
        <source>Stop the scan now</source>
        <translation>立即停止扫描</translation>
    </message>
    <message>
        <source>Controllers found</source>
        <translation>找到的控制器</translation>
    </message>
    <message>
        <source>Baud</source>
        <translation>波特率</translation>
    </message>
    <message>
        <source>Device id</source>
        <translation>设备 ID</translation>
    </message>
    <message>
        <source>Double-click a controller to connect to it</source>
        <translation>双击控制器即可连接</translation>
    </message>
    <message>
        <source>C&amp;onnect</source>
        <translation>连接(&amp;O)</translation>
    </message>
    <message>
        <source>Connect to the selected controller with its baud rate and id</source>
        <translation>以所选控制器的波特率和设备 ID 连接该控制器</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>even</source>
        <translation>偶</translation>
    </message>
    <message>
        <source>odd</source>
        <translation>奇</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>%1:%2 (Modbus TCP)</source>
        <translation>%1:%2（Modbus TCP）</translation>
    </message>
    <message numerus="yes">
        <source>%1, parity %2, %n stop bit(s)</source>
        <translation>
            <numerusform>%1，%2校验，%n 位停止位</numerusform>
        </translation>
    </message>
    <message>
        <source>(no port chosen)</source>
        <translation>（未选择端口）</translation>
    </message>
    <message>
        <source>starting…</source>
        <translation>正在启动…</translation>
    </message>
    <message>
        <source>id %1 at %2 baud</source>
        <translation>ID %1，波特率 %2</translation>
    </message>
    <message>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <source>StepCom is connected on this port: the scan disconnects first.</source>
        <translation>StepCom 正通过此端口连接：扫描前会先断开连接。</translation>
    </message>
    <message numerus="yes">
        <source>Scanning… %n controller(s) found so far.</source>
        <translation>
            <numerusform>正在扫描… 目前已找到 %n 个控制器。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Scan finished: %n controller(s) found. Select one and press Connect.</source>
        <translation>
            <numerusform>扫描完成：找到 %n 个控制器。请选择一个，然后点击“连接”。</numerusform>
        </translation>
    </message>
    <message>
        <source>Scan finished: no controller answered. Check the power, the wiring (A and B swapped?) and the port.</source>
        <translation>扫描完成：没有控制器应答。请检查电源、接线（A、B 是否接反？）和端口。</translation>
    </message>
    <message numerus="yes">
        <source>Scan cancelled: %n controller(s) found.</source>
        <translation>
            <numerusform>扫描已取消：找到 %n 个控制器。</numerusform>
        </translation>
    </message>
    <message>
        <source>Scan stopped: %1</source>
        <translation>扫描已停止：%1</translation>
    </message>
    <message>
        <source>Choose at least one baud rate.</source>
        <translation>请至少选择一个波特率。</translation>
    </message>
    <message>
        <source>Scan stopped: StepCom connected on this port.</source>
        <translation>扫描已停止：StepCom 已通过此端口连接。</translation>
    </message>
    <message numerus="yes">
        <source>%n probe(s), at most about %1 s. A scan only reads; nothing is written.</source>
        <translation>
            <numerusform>共探测 %n 次，最多约 %1 s。扫描只读取，不写入任何数据。</numerusform>
        </translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <source>Scan finished: %1. Press Connect.</source>
        <translation>扫描完成：%1。请按“连接”。</translation>
    </message>
    <message>
        <source>%1:%2 (RTU over TCP)</source>
        <translation>%1:%2（TCP 上的 RTU）</translation>
    </message>
    <message>
        <source>&amp;Add all found</source>
        <translation>全部加入列表(&amp;A)</translation>
    </message>
    <message>
        <source>Put every controller found on the device list (View → Devices on the line)</source>
        <translation>把找到的每台控制器加入设备列表（视图 → 总线上的设备）</translation>
    </message>
    <message>
        <source>Every controller found is on the device list already.</source>
        <translation>找到的控制器都已在设备列表中。</translation>
    </message>
    <message>
        <source>Added to the device list: id %1.</source>
        <translation>已加入设备列表：ID %1。</translation>
    </message>
    <message>
        <source>They answered at different baud rates; give them one baud rate (Device page or Device → Assign device ids…) before working with the list.</source>
        <translation>它们在不同的波特率下应答；使用列表之前，请先给它们统一波特率（设备页面，或 设备 → 分配设备 ID…）。</translation>
    </message>
    <message>
        <source>%1 (answered after %2 ms: connects with a %3 ms timeout)</source>
        <translation>%1（%2 ms 后才应答：将以 %3 ms 超时连接）</translation>
    </message>
    <message>
        <source>fitted to the baud</source>
        <translation>按波特率自动</translation>
    </message>
    <message>
        <source>How long to wait for an answer from each id. Fitted to the baud: the frames, the controller&apos;s 35 ms answer delay and a USB adapter&apos;s latency (67 ms at 9600). A controller that answers later is still found by its late answer; give more for one that answers very slowly.</source>
        <translation>每个 ID 等待应答的时间。按波特率自动：请求帧和应答帧、控制器 35 ms 的应答延时，加上 USB 转换器的延迟（9600 时为 67 ms）。应答更晚的控制器仍可凭其迟到的应答找到；只有应答非常慢的控制器才需要设得更长。</translation>
    </message>
</context>
<context>
    <name>stepcom::BusScanner</name>
    <message>
        <source>no baud rate to try</source>
        <translation>没有可尝试的波特率</translation>
    </message>
    <message>
        <source>scan finished</source>
        <translation>扫描完成</translation>
    </message>
    <message>
        <source>id %1 at %2 — %3</source>
        <translation>ID %1，%2 — %3</translation>
    </message>
    <message>
        <source>a device that refused the first register: %1</source>
        <translation>一台拒绝读取第一个寄存器的设备：%1</translation>
    </message>
    <message>
        <source>a %1-axis controller</source>
        <translation>%1 轴控制器</translation>
    </message>
    <message>
        <source>a controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <source>%1, step angle %2</source>
        <translation>%1，步距角 %2</translation>
    </message>
    <message>
        <source>%1, step angles %2</source>
        <translation>%1，步距角 %2</translation>
    </message>
    <message>
        <source> and </source>
        <translation> 和 </translation>
    </message>
    <message>
        <source> (only %1 of %2 motors answered)</source>
        <translation>（%2 台电机中只有 %1 台应答）</translation>
    </message>
    <message>
        <source>identify id %1</source>
        <translation>识别 ID %1</translation>
    </message>
    <message>
        <source>no device id to try</source>
        <translation>没有要尝试的设备 ID</translation>
    </message>
    <message>
        <source>scan id %1 at %2</source>
        <translation>扫描 ID %1，%2</translation>
    </message>
</context>
<context>
    <name>stepcom::BusSweep</name>
    <message>
        <source>id %1 was not read: E-STOP</source>
        <translation>ID %1 未读取：急停</translation>
    </message>
</context>
<context>
    <name>stepcom::CertificateSection</name>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Commissioning checklist</source>
        <translation>调试检查表</translation>
    </message>
    <message>
        <source>No commissioning checklist was recorded for this machine: this report shows settings, not tests.</source>
        <translation>此机器没有记录调试检查表：本报告只列出设置，不包含测试结果。</translation>
    </message>
    <message>
        <source>Checklist file: %1</source>
        <translation>检查表文件：%1</translation>
    </message>
    <message>
        <source>The checklist was last run with other settings (fingerprint %1); this report&apos;s settings have the fingerprint %2.</source>
        <translation>检查表最后一次执行时的设置不同（指纹 %1）；本报告中设置的指纹为 %2。</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>步骤</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>测量值</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>%1 (attempt %2)</source>
        <translation>%1（第 %2 次）</translation>
    </message>
    <message>
        <source>Software travel limits</source>
        <translation>软件行程限位</translation>
    </message>
    <message>
        <source>StepCom&apos;s own limits for steps, moves to a position and jogs; not controller registers. The limit switches stay the machine&apos;s protection.</source>
        <translation>StepCom 自身对步进、定位运行和点动的限制，不是控制器寄存器。机器的保护仍然是限位开关。</translation>
    </message>
    <message>
        <source>Motor</source>
        <translation>电机</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>最小</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>最大</translation>
    </message>
    <message>
        <source>open</source>
        <translation>不限</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>Signatures</source>
        <translation>签字</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>职责</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>姓名</translation>
    </message>
    <message>
        <source>Signature</source>
        <translation>签名</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>日期</translation>
    </message>
    <message>
        <source>Commissioned by</source>
        <translation>调试人</translation>
    </message>
    <message>
        <source>Accepted by (customer)</source>
        <translation>验收人（客户）</translation>
    </message>
    <message>
        <source>Read from StepCom&apos;s built-in simulator, not from a machine: nothing here can be signed for a machine.</source>
        <translation>读自 StepCom 内置仿真器，而非真实机器：此处不能为任何机器签字。</translation>
    </message>
</context>
<context>
    <name>stepcom::Checklist</name>
    <message>
        <source>%1: a result is passed, failed or skipped, not pending</source>
        <translation>%1：结果应为通过、失败或跳过，而不是未执行</translation>
    </message>
    <message>
        <source>%1: the attempt has no valid time</source>
        <translation>%1：该次执行没有有效的时间</translation>
    </message>
    <message>
        <source>%1: the note has %2 characters (at most %3)</source>
        <translation>%1：备注有 %2 个字符（最多 %3 个）</translation>
    </message>
    <message>
        <source>%1: %2 measurements (at most %3)</source>
        <translation>%1：%2 个测量值（最多 %3 个）</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a measurement key (1-40 of a-z, 0-9, _ and .)</source>
        <translation>%1：“%2”不是测量值名称（1-40 个 a-z、0-9、_ 和 . 字符）</translation>
    </message>
    <message>
        <source>%1: the measurement &quot;%2&quot; is too long</source>
        <translation>%1：测量值“%2”过长</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a step of this checklist</source>
        <translation>“%1”不是此检查表中的步骤</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a step of this checklist (%2 motor(s))</source>
        <translation>“%1”不是此检查表中的步骤（%2 个电机）</translation>
    </message>
    <message>
        <source>%1: %2 attempts (at most %3)</source>
        <translation>%1：执行了 %2 次（最多 %3 次）</translation>
    </message>
    <message>
        <source>%1: the attempts must be numbered upwards (found %2 after %3)</source>
        <translation>%1：执行次序必须递增（%3 之后出现 %2）</translation>
    </message>
    <message>
        <source>Not started</source>
        <translation>未开始</translation>
    </message>
    <message>
        <source>In progress: not every step was run</source>
        <translation>进行中：尚有步骤未执行</translation>
    </message>
    <message>
        <source>Failed: at least one step failed</source>
        <translation>未通过：至少一个步骤失败</translation>
    </message>
    <message>
        <source>Passed, with skipped steps</source>
        <translation>通过，有跳过的步骤</translation>
    </message>
    <message>
        <source>Passed: every step passed</source>
        <translation>通过：所有步骤均通过</translation>
    </message>
    <message>
        <source>%1 of %2 steps passed, %3 failed, %4 skipped, %5 not run</source>
        <translation>%2 个步骤中 %1 个通过，%3 个失败，%4 个跳过，%5 个未执行</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistBacklashStep</name>
    <message>
        <source>Put the gauge on the carriage. Run it? The axis will move.</source>
        <translation>请将百分表放在滑台上。是否运行？轴将会移动。</translation>
    </message>
    <message>
        <source>Reading %1 of %2, %3: type what the gauge shows and press Enter.</source>
        <translation>第 %1 个读数（共 %2 个），%3：请输入百分表的读数并按回车。</translation>
    </message>
    <message>
        <source>&amp;Distance of each move:</source>
        <translation>每次移动的距离(&amp;D)：</translation>
    </message>
    <message>
        <source>C&amp;ycles:</source>
        <translation>循环次数(&amp;Y)：</translation>
    </message>
    <message>
        <source>Distance of each move</source>
        <translation>每次移动的距离</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>循环次数</translation>
    </message>
    <message>
        <source>Gauge: </source>
        <translation>百分表：</translation>
    </message>
    <message>
        <source>Gauge reading</source>
        <translation>百分表读数</translation>
    </message>
    <message>
        <source>Start the &amp;backlash test</source>
        <translation>开始反向间隙测试(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Enter reading</source>
        <translation>输入读数(&amp;E)</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistCalibrationStep</name>
    <message>
        <source>Moving…</source>
        <translation>正在运行…</translation>
    </message>
    <message>
        <source>The pitch was not written.</source>
        <translation>螺距未写入。</translation>
    </message>
    <message>
        <source>Passed: the corrected pitch is written and verified.</source>
        <translation>通过：修正后的螺距已写入并校验。</translation>
    </message>
    <message>
        <source>Passed: the axis moved what it was told; the pitch stays %1 %2.</source>
        <translation>通过：轴的实际行程与指令一致；螺距保持 %1 %2。</translation>
    </message>
    <message>
        <source>Write the corrected pitch %1 %2…</source>
        <translation>写入修正后的螺距 %1 %2…</translation>
    </message>
    <message>
        <source>Measured ÷ commanded = %1: the pitch %2 %3 should be %4 %3.</source>
        <translation>实测 ÷ 指令 = %1：螺距 %2 %3 应为 %4 %3。</translation>
    </message>
    <message>
        <source>Commanded: </source>
        <translation>指令：</translation>
    </message>
    <message>
        <source>Measured: </source>
        <translation>实测：</translation>
    </message>
    <message>
        <source>Move this distance</source>
        <translation>运行此距离</translation>
    </message>
    <message>
        <source>Propose the pitch</source>
        <translation>计算螺距</translation>
    </message>
    <message>
        <source>Commanded distance</source>
        <translation>指令距离</translation>
    </message>
    <message>
        <source>Measured distance</source>
        <translation>实测距离</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistDirectionStep</name>
    <message>
        <source>The direction register is not read yet.</source>
        <translation>方向寄存器尚未读取。</translation>
    </message>
    <message>
        <source>Moving…</source>
        <translation>正在运行…</translation>
    </message>
    <message>
        <source>The direction register is written and verified. Repeat the step to confirm the axis now moves toward +.</source>
        <translation>方向寄存器已写入并校验。请重复此步骤，确认轴现在朝 + 方向运动。</translation>
    </message>
    <message>
        <source>The direction register was not written.</source>
        <translation>方向寄存器未写入。</translation>
    </message>
    <message>
        <source>Passed: the axis moves toward + with the direction as configured.</source>
        <translation>通过：按当前方向设置，轴朝 + 方向运动。</translation>
    </message>
    <message>
        <source>Flip the direction to %1…</source>
        <translation>将方向改为 %1…</translation>
    </message>
    <message>
        <source>Failed: the axis moved toward −. Flip the direction register, then repeat the step.</source>
        <translation>未通过：轴朝 − 方向运动。请修改方向寄存器，然后重复此步骤。</translation>
    </message>
    <message>
        <source>Move a small step</source>
        <translation>运行一小步</translation>
    </message>
    <message>
        <source>Yes, toward +</source>
        <translation>是，朝 +</translation>
    </message>
    <message>
        <source>No, toward −</source>
        <translation>否，朝 −</translation>
    </message>
    <message>
        <source>Small step distance</source>
        <translation>小步距离</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistFile</name>
    <message>
        <source>null</source>
        <translation>null</translation>
    </message>
    <message>
        <source>true/false</source>
        <translation>true/false</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>数字</translation>
    </message>
    <message>
        <source>a text</source>
        <translation>文本</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>列表</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>对象</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>空</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>文件为空</translation>
    </message>
    <message>
        <source>the file is %1 bytes: far too large for a checklist</source>
        <translation>文件有 %1 字节：作为检查表太大</translation>
    </message>
    <message>
        <source>not valid JSON at line %1, column %2: %3</source>
        <translation>第 %1 行第 %2 列不是有效的 JSON：%3</translation>
    </message>
    <message>
        <source>the file holds a JSON list, not a checklist</source>
        <translation>文件中是 JSON 列表，不是检查表</translation>
    </message>
    <message>
        <source>… and %1 more problems</source>
        <translation>……另有 %1 个问题</translation>
    </message>
    <message>
        <source>%1unknown field &quot;%2&quot; (allowed: %3)</source>
        <translation>%1未知字段“%2”（允许：%3）</translation>
    </message>
    <message>
        <source>%1&quot;%2&quot; must be a text, found %3</source>
        <translation>%1“%2”必须是文本，实际为%3</translation>
    </message>
    <message>
        <source>this is a profile, not a checklist</source>
        <translation>这是参数文件，不是检查表</translation>
    </message>
    <message>
        <source>not a StepCom checklist: &quot;format&quot; must be &quot;%1&quot;</source>
        <translation>不是 StepCom 检查表：“format”必须为“%1”</translation>
    </message>
    <message>
        <source>checklist schema %1 is newer than this StepCom reads (%2): update StepCom</source>
        <translation>检查表格式版本 %1 比本 StepCom 能读取的（%2）更新：请升级 StepCom</translation>
    </message>
    <message>
        <source>&quot;schema&quot; must be %1</source>
        <translation>“schema”必须为 %1</translation>
    </message>
    <message>
        <source>the checklist is for register map &quot;%1&quot;, but this map is &quot;%2&quot;</source>
        <translation>检查表属于寄存器表“%1”，但当前寄存器表是“%2”</translation>
    </message>
    <message>
        <source>&quot;machine&quot; and &quot;settingsFingerprint&quot; hold at most 200 characters</source>
        <translation>“machine”和“settingsFingerprint”最多 200 个字符</translation>
    </message>
    <message>
        <source>&quot;steps&quot; must be a list, found %1</source>
        <translation>“steps”必须是列表，实际为%1</translation>
    </message>
    <message>
        <source>step %1</source>
        <translation>第 %1 个步骤</translation>
    </message>
    <message>
        <source>%1: must be an object, found %2</source>
        <translation>%1：必须是对象，实际为%2</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; appears more than once</source>
        <translation>%1：“%2”出现了多次</translation>
    </message>
    <message>
        <source>%1: &quot;attempts&quot; must be a list, found %2</source>
        <translation>%1：“attempts”必须是列表，实际为%2</translation>
    </message>
    <message>
        <source>%1: &quot;attempt&quot; must be a whole number from 1</source>
        <translation>%1：“attempt”必须是从 1 开始的整数</translation>
    </message>
    <message>
        <source>%1: &quot;result&quot; must be passed, failed or skipped, found &quot;%2&quot;</source>
        <translation>%1：“result”必须是 passed、failed 或 skipped，实际为“%2”</translation>
    </message>
    <message>
        <source>%1: &quot;time&quot; is not a date and time (2024-05-31T14:02:00Z): &quot;%2&quot;</source>
        <translation>%1：“time”不是日期时间（2024-05-31T14:02:00Z）：“%2”</translation>
    </message>
    <message>
        <source>%1: &quot;measurements&quot; must be a list, found %2</source>
        <translation>%1：“measurements”必须是列表，实际为%2</translation>
    </message>
    <message>
        <source>no register map to check the checklist against</source>
        <translation>没有可用于检查此检查表的寄存器表</translation>
    </message>
    <message>
        <source>%1: no such file</source>
        <translation>%1：文件不存在</translation>
    </message>
    <message>
        <source>%1: %2 bytes, far too large for a checklist</source>
        <translation>%1：%2 字节，作为检查表太大</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistFlashStep</name>
    <message>
        <source>Not connected: nothing was sent.</source>
        <translation>未连接：没有发送任何命令。</translation>
    </message>
    <message>
        <source>Not every setting is read yet (%1): read all first.</source>
        <translation>尚有参数未读取（%1）：请先全部读取。</translation>
    </message>
    <message>
        <source>Saving to flash…</source>
        <translation>正在保存到闪存…</translation>
    </message>
    <message>
        <source>Failed: the save to flash was not done (see the messages).</source>
        <translation>未通过：未能保存到闪存（见消息）。</translation>
    </message>
    <message numerus="yes">
        <source>%n setting(s) differ</source>
        <translation>
            <numerusform>%n 个参数不一致</numerusform>
        </translation>
    </message>
    <message>
        <source>Failed: after the save these settings read back differently: %1</source>
        <translation>未通过：保存后回读的这些参数不一致：%1</translation>
    </message>
    <message>
        <source>Failed: the settings could not be read back: %1</source>
        <translation>未通过：无法回读参数：%1</translation>
    </message>
    <message numerus="yes">
        <source>%n setting(s) read back unchanged</source>
        <translation>
            <numerusform>回读 %n 个参数，均未改变</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Passed: saved to flash, and all %n setting(s) read back unchanged.</source>
        <translation>
            <numerusform>通过：已保存到闪存，回读全部 %n 个参数均未改变。</numerusform>
        </translation>
    </message>
    <message>
        <source>Save to flash and read back</source>
        <translation>保存到闪存并回读</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistInputStep</name>
    <message>
        <source>The input setting is written and verified. Repeat the step to confirm.</source>
        <translation>输入设置已写入并校验。请重复此步骤以确认。</translation>
    </message>
    <message>
        <source>The input setting was not written.</source>
        <translation>输入设置未写入。</translation>
    </message>
    <message>
        <source>The inputs are not known yet: connect and wait for the status.</source>
        <translation>输入状态尚未知：请连接并等待状态刷新。</translation>
    </message>
    <message>
        <source>Watching the inputs: press the %1 of motor %2 now, let go, then click Done.</source>
        <translation>正在监视输入：请现在按下电机 %2 的%1，松开后点击“完成”。</translation>
    </message>
    <message>
        <source>Write the fix (%1)…</source>
        <translation>写入修正（%1）…</translation>
    </message>
    <message>
        <source>Press it now</source>
        <translation>现在按下</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>完成</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistMotionStep</name>
    <message>
        <source>Not connected: nothing was sent.</source>
        <translation>未连接：没有发送任何命令。</translation>
    </message>
    <message>
        <source>Nothing to run: the homing order is empty, every motor runs, or the path&apos;s registers are not read yet.</source>
        <translation>无可运行的内容：回零顺序为空、所有电机都在运行，或路径寄存器尚未读取。</translation>
    </message>
    <message>
        <source>Running…</source>
        <translation>正在运行…</translation>
    </message>
    <message>
        <source>The command was not acknowledged: nothing moved.</source>
        <translation>命令未被确认：没有任何运动。</translation>
    </message>
    <message>
        <source>Home motor %1</source>
        <translation>电机 %1 回零</translation>
    </message>
    <message>
        <source>Home in order</source>
        <translation>按顺序回零</translation>
    </message>
    <message>
        <source>Run the test</source>
        <translation>运行测试</translation>
    </message>
    <message>
        <source>The configured arc</source>
        <translation>已设置的圆弧</translation>
    </message>
    <message>
        <source>The configured line</source>
        <translation>已设置的直线</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistPage</name>
    <message>
        <source>Commissioning checklist</source>
        <translation>调试检查表</translation>
    </message>
    <message>
        <source>The checklist file %1 cannot be used, and nothing is saved over it: %2</source>
        <translation>检查表文件 %1 无法使用，也不会被覆盖：%2</translation>
    </message>
    <message>
        <source>The result is not saved: %1</source>
        <translation>结果未保存：%1</translation>
    </message>
    <message>
        <source>The machine&apos;s profile</source>
        <translation>设备的参数文件</translation>
    </message>
    <message>
        <source>StepCom profiles (*.json)</source>
        <translation>StepCom 参数文件 (*.json)</translation>
    </message>
    <message>
        <source>No profile chosen: the progress is kept in %1. Choose the machine&apos;s profile to keep it beside it.</source>
        <translation>未选择参数文件：进度保存在 %1。选择设备的参数文件后，进度将保存在它旁边。</translation>
    </message>
    <message>
        <source>Profile %1 — the progress is kept in %2</source>
        <translation>参数文件 %1 — 进度保存在 %2</translation>
    </message>
    <message>
        <source>Choose &amp;profile…</source>
        <translation>选择参数文件(&amp;P)…</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistProofStep</name>
    <message>
        <source>auto</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>After the moves out: %1 mm</source>
        <translation>外移之后：%1 mm</translation>
    </message>
    <message>
        <source>After the moves back: %1 mm</source>
        <translation>返回之后：%1 mm</translation>
    </message>
    <message>
        <source>Run it? The axis will move.</source>
        <translation>是否运行？轴将会移动。</translation>
    </message>
    <message>
        <source>Write the recommended acceleration %1…</source>
        <translation>写入推荐的加速度 %1…</translation>
    </message>
    <message>
        <source>Write the recommended speed %1 rpm…</source>
        <translation>写入推荐的速度 %1 rpm…</translation>
    </message>
    <message>
        <source>The recommendation was not written.</source>
        <translation>推荐值未写入。</translation>
    </message>
    <message>
        <source>The recommendation is written and verified. Run the lost-step test again to prove it.</source>
        <translation>推荐值已写入并校验。请再次运行丢步测试加以验证。</translation>
    </message>
    <message>
        <source>C&amp;ycles:</source>
        <translation>循环次数(&amp;Y)：</translation>
    </message>
    <message>
        <source>&amp;Distance of each move:</source>
        <translation>每次移动的距离(&amp;D)：</translation>
    </message>
    <message>
        <source>Margin: &amp;from, to, step:</source>
        <translation>余量：起始、终止、步长(&amp;F)：</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>循环次数</translation>
    </message>
    <message>
        <source>Distance of each move</source>
        <translation>每次移动的距离</translation>
    </message>
    <message>
        <source>Margin from</source>
        <translation>余量起始值</translation>
    </message>
    <message>
        <source>Margin to</source>
        <translation>余量终止值</translation>
    </message>
    <message>
        <source>Margin step</source>
        <translation>余量步长</translation>
    </message>
    <message>
        <source>Search the &amp;acceleration instead of the speed</source>
        <translation>改为搜索加速度(&amp;A)</translation>
    </message>
    <message>
        <source>Run the &amp;lost-step test</source>
        <translation>运行丢步测试(&amp;L)</translation>
    </message>
    <message>
        <source>Find the &amp;margin</source>
        <translation>寻找余量(&amp;M)</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <source>Test progress</source>
        <translation>测试进度</translation>
    </message>
    <message>
        <source>The margin search: lost mm at each value tested</source>
        <translation>余量搜索：每个测试值下丢失的 mm</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistRunInStep</name>
    <message>
        <source>Open the Sequence page</source>
        <translation>打开序列页面</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistStep</name>
    <message>
        <source>Not run</source>
        <translation>未执行</translation>
    </message>
    <message>
        <source>Passed</source>
        <translation>通过</translation>
    </message>
    <message>
        <source>Failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <source>Skipped</source>
        <translation>跳过</translation>
    </message>
    <message>
        <source>direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>travel calibration</source>
        <translation>行程校准</translation>
    </message>
    <message>
        <source>positive limit input</source>
        <translation>正限位输入</translation>
    </message>
    <message>
        <source>negative limit input</source>
        <translation>反限位输入</translation>
    </message>
    <message>
        <source>home input</source>
        <translation>原点输入</translation>
    </message>
    <message>
        <source>homing</source>
        <translation>回原点</translation>
    </message>
    <message>
        <source>Machine: homing order</source>
        <translation>整机：回原点顺序</translation>
    </message>
    <message>
        <source>Machine: interpolation test</source>
        <translation>整机：插补测试</translation>
    </message>
    <message>
        <source>Machine: save to flash and read back</source>
        <translation>整机：保存到闪存并读回</translation>
    </message>
    <message>
        <source>Motor %1: %2</source>
        <translation>电机 %1：%2</translation>
    </message>
    <message>
        <source>Move motor %1 a small step forward. Did the axis move toward + ? No offers to flip its direction register.</source>
        <translation>让电机 %1 正向走一小步。轴是否朝 + 方向移动？选“否”会建议翻转其方向寄存器。</translation>
    </message>
    <message>
        <source>Move motor %1 by a distance you choose, measure what the axis really moved and type it in: StepCom proposes the corrected pitch (pitch × measured ÷ commanded).</source>
        <translation>让电机 %1 运行一段您选择的距离，测量轴实际移动的距离并输入：StepCom 会建议修正后的螺距（螺距 × 实测 ÷ 指令）。</translation>
    </message>
    <message>
        <source>Press the positive limit switch of motor %1 by hand: StepCom watches the inputs and compares the one that changed with the configuration.</source>
        <translation>用手按下电机 %1 的正限位开关：StepCom 监视输入口，并将发生变化的输入与配置比较。</translation>
    </message>
    <message>
        <source>Press the negative limit switch of motor %1 by hand: StepCom watches the inputs and compares the one that changed with the configuration.</source>
        <translation>用手按下电机 %1 的反限位开关：StepCom 监视输入口，并将发生变化的输入与配置比较。</translation>
    </message>
    <message>
        <source>Press the home switch of motor %1 by hand (often the negative limit&apos;s switch): StepCom compares the input that changed with the configuration.</source>
        <translation>用手按下电机 %1 的原点开关（通常就是反限位开关）：StepCom 将发生变化的输入与配置比较。</translation>
    </message>
    <message>
        <source>Home motor %1 and check that it ended on its home switch, referenced.</source>
        <translation>让电机 %1 回原点，并确认它停在原点开关上、已建立参考点。</translation>
    </message>
    <message>
        <source>Home the machine in the configured order and check that every axis in the order ended referenced.</source>
        <translation>按设定的顺序让整机回原点，并确认顺序中的每个轴都已建立参考点。</translation>
    </message>
    <message>
        <source>Run the configured arc or line and check that the axes ended at its end point.</source>
        <translation>运行设定的圆弧或直线，并确认各轴停在其终点。</translation>
    </message>
    <message>
        <source>Save the parameters to flash, read them back and compare them with what was written.</source>
        <translation>将参数保存到闪存，读回并与写入的值比较。</translation>
    </message>
    <message>
        <source>Commanded distance</source>
        <translation>指令距离</translation>
    </message>
    <message>
        <source>Measured distance</source>
        <translation>实测距离</translation>
    </message>
    <message>
        <source>Pitch before</source>
        <translation>原螺距</translation>
    </message>
    <message>
        <source>Pitch after</source>
        <translation>新螺距</translation>
    </message>
    <message>
        <source>Moved toward +</source>
        <translation>朝 + 方向移动</translation>
    </message>
    <message>
        <source>Direction before</source>
        <translation>原方向</translation>
    </message>
    <message>
        <source>Direction after</source>
        <translation>新方向</translation>
    </message>
    <message>
        <source>Input configured</source>
        <translation>配置的输入</translation>
    </message>
    <message>
        <source>Input that answered</source>
        <translation>响应的输入</translation>
    </message>
    <message>
        <source>Fix written</source>
        <translation>已写入的修正</translation>
    </message>
    <message>
        <source>End position</source>
        <translation>终点位置</translation>
    </message>
    <message>
        <source>Expected end</source>
        <translation>预期终点</translation>
    </message>
    <message>
        <source>Homing order</source>
        <translation>回原点顺序</translation>
    </message>
    <message>
        <source>Read back</source>
        <translation>读回</translation>
    </message>
    <message>
        <source>keeps its steps</source>
        <translation>未丢步</translation>
    </message>
    <message>
        <source>backlash</source>
        <translation>反向间隙</translation>
    </message>
    <message>
        <source>Prove that motor %1 keeps its steps at its own speed and acceleration: the count against the home switch before and after moves out fast and back slowly, and the other way. Then find the margin: the test at each speed on the way up, to the first loss.</source>
        <translation>验证电机 %1 在其自身的速度和加速度下不丢步：在快速外移、慢速返回以及反过来的移动前后，以原点开关对照计数。然后寻找余量：逐步升高转速运行该测试，直到第一次丢步。</translation>
    </message>
    <message>
        <source>Put a dial gauge on motor %1&apos;s carriage. StepCom approaches a point from one side, then moves on and back; type what the gauge shows after each move.</source>
        <translation>将百分表放在电机 %1 的滑台上。StepCom 从一侧趋近某一点，然后继续前移并返回；每次移动后输入百分表的读数。</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>结论</translation>
    </message>
    <message>
        <source>Tested at speed</source>
        <translation>测试速度</translation>
    </message>
    <message>
        <source>Tested at acceleration</source>
        <translation>测试加速度</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>循环次数</translation>
    </message>
    <message>
        <source>Distance of each move</source>
        <translation>每次移动的距离</translation>
    </message>
    <message>
        <source>Lost after the moves out</source>
        <translation>外移后的丢失量</translation>
    </message>
    <message>
        <source>Lost after the moves back</source>
        <translation>返回后的丢失量</translation>
    </message>
    <message>
        <source>Switch repeatability</source>
        <translation>开关重复性</translation>
    </message>
    <message>
        <source>Highest speed kept</source>
        <translation>未丢步的最高速度</translation>
    </message>
    <message>
        <source>First speed lost</source>
        <translation>首个丢步的速度</translation>
    </message>
    <message>
        <source>Recommended speed</source>
        <translation>推荐速度</translation>
    </message>
    <message>
        <source>Highest acceleration kept</source>
        <translation>未丢步的最高加速度</translation>
    </message>
    <message>
        <source>First acceleration lost</source>
        <translation>首个丢步的加速度</translation>
    </message>
    <message>
        <source>Recommended acceleration</source>
        <translation>推荐加速度</translation>
    </message>
    <message>
        <source>Backlash</source>
        <translation>反向间隙</translation>
    </message>
    <message>
        <source>Spread</source>
        <translation>极差</translation>
    </message>
    <message>
        <source>Gauge readings</source>
        <translation>百分表读数</translation>
    </message>
    <message>
        <source>Taken on</source>
        <translation>测试对象</translation>
    </message>
    <message>
        <source>Machine: run-in of its cycle</source>
        <translation>整机：工作循环试运行</translation>
    </message>
    <message>
        <source>Run the machine&apos;s cycle on the Sequence page for a number of cycles, with the lost-step check at the end. The run-in&apos;s result is recorded here: cycles, cycle time and whether every axis kept its steps.</source>
        <translation>在序列页面上将机器的工作循环运行若干次，结束时检查丢步。试运行的结果记录在这里：循环次数、循环时间以及每根轴是否未丢步。</translation>
    </message>
    <message>
        <source>Sequence</source>
        <translation>序列</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>Cycles done</source>
        <translation>完成的循环</translation>
    </message>
    <message>
        <source>Shortest cycle</source>
        <translation>最短循环</translation>
    </message>
    <message>
        <source>Median cycle</source>
        <translation>中位循环</translation>
    </message>
    <message>
        <source>Longest cycle</source>
        <translation>最长循环</translation>
    </message>
    <message>
        <source>Lost-step check</source>
        <translation>丢步检查</translation>
    </message>
</context>
<context>
    <name>stepcom::ChecklistStepWidget</name>
    <message>
        <source>Skipped.</source>
        <translation>已跳过。</translation>
    </message>
    <message>
        <source>Not connected: nothing was written.</source>
        <translation>未连接：没有写入任何内容。</translation>
    </message>
    <message>
        <source>&amp;Note:</source>
        <translation>备注(&amp;N)：</translation>
    </message>
    <message>
        <source>S&amp;kip this step</source>
        <translation>跳过此步骤(&amp;K)</translation>
    </message>
</context>
<context>
    <name>stepcom::CommissioningReport</name>
    <message>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <source>Device id</source>
        <translation>设备地址</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Baud rate (register)</source>
        <translation>波特率（寄存器）</translation>
    </message>
    <message>
        <source>Register map</source>
        <translation>寄存器表</translation>
    </message>
    <message>
        <source>round trips: %1</source>
        <translation>往返次数：%1</translation>
    </message>
    <message>
        <source>System mode</source>
        <translation>系统模式</translation>
    </message>
    <message>
        <source>Homing order</source>
        <translation>回零顺序</translation>
    </message>
    <message>
        <source>first: %1, then: %2</source>
        <translation>先：%1，后：%2</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>日期</translation>
    </message>
    <message>
        <source>StepCom version</source>
        <translation>StepCom 版本</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>键名</translation>
    </message>
    <message>
        <source>Register</source>
        <translation>寄存器</translation>
    </message>
    <message>
        <source>Input wiring</source>
        <translation>输入接线</translation>
    </message>
    <message>
        <source>Motor</source>
        <translation>电机</translation>
    </message>
    <message>
        <source>Positive limit</source>
        <translation>正限位</translation>
    </message>
    <message>
        <source>Negative limit</source>
        <translation>负限位</translation>
    </message>
    <message>
        <source>Home input</source>
        <translation>原点输入</translation>
    </message>
    <message>
        <source>No suspicious wiring found.</source>
        <translation>未发现可疑接线。</translation>
    </message>
    <message>
        <source>Arc and line interpolation</source>
        <translation>圆弧与直线插补</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>圆弧</translation>
    </message>
    <message>
        <source>Arc mode</source>
        <translation>圆弧模式</translation>
    </message>
    <message>
        <source>Arc start</source>
        <translation>圆弧起点</translation>
    </message>
    <message>
        <source>Arc end</source>
        <translation>圆弧终点</translation>
    </message>
    <message>
        <source>Arc centre</source>
        <translation>圆弧圆心</translation>
    </message>
    <message>
        <source>Arc middle point</source>
        <translation>圆弧中间点</translation>
    </message>
    <message>
        <source>Arc direction</source>
        <translation>圆弧方向</translation>
    </message>
    <message>
        <source>Arc speed</source>
        <translation>圆弧速度</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>直线</translation>
    </message>
    <message>
        <source>Line start</source>
        <translation>直线起点</translation>
    </message>
    <message>
        <source>Line end</source>
        <translation>直线终点</translation>
    </message>
    <message>
        <source>Line speed</source>
        <translation>直线速度</translation>
    </message>
    <message>
        <source>The arc cannot be drawn: %1</source>
        <translation>无法绘制圆弧：%1</translation>
    </message>
    <message>
        <source>XY picture of the arc and the line</source>
        <translation>圆弧与直线的 XY 图</translation>
    </message>
    <message>
        <source>Commissioning report</source>
        <translation>调试报告</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>Controller (as the profile records it)</source>
        <translation>控制器（参数文件中的记录）</translation>
    </message>
    <message>
        <source>none: made from a file, not read from a controller</source>
        <translation>无：根据文件生成，未读取控制器</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>波特率</translation>
    </message>
    <message>
        <source>the profile was made with %1</source>
        <translation>参数文件由 %1 生成</translation>
    </message>
    <message>
        <source>Profile file</source>
        <translation>参数文件</translation>
    </message>
    <message>
        <source>Profile saved</source>
        <translation>参数文件保存于</translation>
    </message>
    <message>
        <source>%1 by StepCom %2</source>
        <translation>%1，StepCom %2</translation>
    </message>
    <message>
        <source>Report date</source>
        <translation>报告日期</translation>
    </message>
    <message>
        <source>What of the profile this register map cannot show</source>
        <translation>此寄存器表无法显示的参数文件内容</translation>
    </message>
    <message>
        <source>Commissioning report (from a profile file)</source>
        <translation>调试报告（来自参数文件）</translation>
    </message>
    <message>
        <source>Made from the profile file %1, not read from a controller: these are the values the file holds; a controller may hold others.</source>
        <translation>根据参数文件 %1 生成，未读取控制器：这些是文件中的值，控制器中的值可能不同。</translation>
    </message>
    <message>
        <source>Settings fingerprint</source>
        <translation>设置指纹</translation>
    </message>
    <message>
        <source>Values read</source>
        <translation>数值读取时间</translation>
    </message>
    <message>
        <source>Flash</source>
        <translation>闪存</translation>
    </message>
    <message>
        <source>unknown: this program did not follow the writes</source>
        <translation>未知：本程序没有跟踪写入</translation>
    </message>
    <message>
        <source>saved: nothing written since connecting or since the last save to flash</source>
        <translation>已保存：自连接以来或上次保存到闪存以来没有写入</translation>
    </message>
    <message>
        <source>NOT saved: values were written since the last save to flash and are lost at power-off</source>
        <translation>未保存：上次保存到闪存之后写入过数值，断电后会丢失</translation>
    </message>
    <message>
        <source>not supported by this controller</source>
        <translation>此控制器不支持</translation>
    </message>
    <message>
        <source>Not supported by this controller (it refuses to read them, a firmware variant): %1</source>
        <translation>此控制器不支持（控制器拒绝读取，属于固件变体）：%1</translation>
    </message>
    <message>
        <source>Link, as measured</source>
        <translation>实测通信</translation>
    </message>
    <message>
        <source>StepCom&apos;s built-in simulator -- not a machine</source>
        <translation>StepCom 内置仿真器 —— 不是真实机器</translation>
    </message>
    <message>
        <source>%1 -- simulator, not a machine</source>
        <translation>%1 —— 仿真器，不是真实机器</translation>
    </message>
    <message>
        <source>SIMULATOR -- NOT A MACHINE: these values were read from StepCom&apos;s built-in simulator. This sheet certifies no machine.</source>
        <translation>仿真器 —— 不是真实机器：这些值读自 StepCom 内置仿真器。本报告不证明任何机器。</translation>
    </message>
</context>
<context>
    <name>stepcom::ConnectionPage</name>
    <message>
        <source>Disconnected.</source>
        <translation>已断开连接。</translation>
    </message>
    <message>
        <source>Connection lost: %1</source>
        <translation>连接中断：%1</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Connect through</source>
        <translation>连接方式</translation>
    </message>
    <message>
        <source>&amp;Serial (RTU)</source>
        <translation>串口 RTU(&amp;S)</translation>
    </message>
    <message>
        <source>Modbus RTU over RS-485 or RS-232, e.g. a USB adapter</source>
        <translation>经 RS-485 或 RS-232 的 Modbus RTU，例如使用 USB 转换器</translation>
    </message>
    <message>
        <source>Modbus &amp;TCP</source>
        <translation>Modbus TCP(&amp;T)</translation>
    </message>
    <message>
        <source>Modbus TCP, e.g. through an Ethernet-to-RS-485 gateway</source>
        <translation>Modbus TCP，例如经以太网转 RS-485 网关</translation>
    </message>
    <message>
        <source>Built-in si&amp;mulator</source>
        <translation>内置仿真器(&amp;M)</translation>
    </message>
    <message>
        <source>A simulated controller inside StepCom: try every page without a machine</source>
        <translation>StepCom 内置的仿真控制器：无需设备即可试用所有页面</translation>
    </message>
    <message>
        <source>Serial port</source>
        <translation>串口</translation>
    </message>
    <message>
        <source>&amp;Port:</source>
        <translation>端口(&amp;P)：</translation>
    </message>
    <message>
        <source>The serial port, e.g. /dev/ttyUSB0 or COM3. Any path can be typed: pseudo-terminals are not listed.</source>
        <translation>串口，例如 /dev/ttyUSB0 或 COM3。可以输入任意路径：伪终端不会列出。</translation>
    </message>
    <message>
        <source>/dev/ttyUSB0 or a path</source>
        <translation>/dev/ttyUSB0 或其他路径</translation>
    </message>
    <message>
        <source>Re&amp;fresh</source>
        <translation>刷新(&amp;F)</translation>
    </message>
    <message>
        <source>List the serial ports again (after plugging in an adapter)</source>
        <translation>重新列出串口（插入转换器后使用）</translation>
    </message>
    <message>
        <source>&amp;Baud rate:</source>
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <source>The controller&apos;s baud rate (register 40213); factory setting 9600</source>
        <translation>控制器的波特率（寄存器 40213）；出厂设置为 9600</translation>
    </message>
    <message>
        <source>Parit&amp;y:</source>
        <translation>校验(&amp;Y)：</translation>
    </message>
    <message>
        <source>The controller uses no parity (8N1) unless set otherwise</source>
        <translation>除非另有设置，控制器使用无校验（8N1）</translation>
    </message>
    <message>
        <source>None</source>
        <translation>无校验</translation>
    </message>
    <message>
        <source>Even</source>
        <translation>偶校验</translation>
    </message>
    <message>
        <source>Odd</source>
        <translation>奇校验</translation>
    </message>
    <message>
        <source>St&amp;op bits:</source>
        <translation>停止位(&amp;O)：</translation>
    </message>
    <message>
        <source>The controller uses 1 stop bit</source>
        <translation>控制器使用 1 位停止位</translation>
    </message>
    <message>
        <source>Modbus TCP</source>
        <translation>Modbus TCP</translation>
    </message>
    <message>
        <source>&amp;Host:</source>
        <translation>主机(&amp;H)：</translation>
    </message>
    <message>
        <source>Host name or IP address of the gateway or controller</source>
        <translation>网关或控制器的主机名或 IP 地址</translation>
    </message>
    <message>
        <source>192.168.0.7</source>
        <translation>192.168.0.7</translation>
    </message>
    <message>
        <source>TCP p&amp;ort:</source>
        <translation>TCP 端口(&amp;O)：</translation>
    </message>
    <message>
        <source>TCP port of the Modbus server; 502 is the standard</source>
        <translation>Modbus 服务器的 TCP 端口；标准端口为 502</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <source>Device &amp;id:</source>
        <translation>设备 ID(&amp;I)：</translation>
    </message>
    <message>
        <source>The controller&apos;s Modbus address (register 40212); factory setting 1. Use Scan bus when it is not known.</source>
        <translation>控制器的 Modbus 地址（寄存器 40212）；出厂设置为 1。不知道地址时请使用“扫描总线”。</translation>
    </message>
    <message>
        <source>Tim&amp;eout:</source>
        <translation>超时(&amp;E)：</translation>
    </message>
    <message>
        <source>How long to wait for each answer before trying again</source>
        <translation>每次等待应答的时间，超时后重试</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>&amp;Retries:</source>
        <translation>重试次数(&amp;R)：</translation>
    </message>
    <message>
        <source>How often an unanswered request is sent again</source>
        <translation>无应答的请求重新发送的次数</translation>
    </message>
    <message>
        <source>Built-in simulator</source>
        <translation>内置仿真器</translation>
    </message>
    <message>
        <source>A simulated controller runs inside StepCom and answers like the real one: every page can be tried without a machine. Nothing reaches real hardware.</source>
        <translation>仿真控制器在 StepCom 内部运行，应答方式与真实控制器相同：无需设备即可试用所有页面。不会向真实硬件发送任何数据。</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>通信链路</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>连接(&amp;C)</translation>
    </message>
    <message>
        <source>Connect and read every parameter (nothing is written)</source>
        <translation>连接并读取所有参数（不写入任何数据）</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>断开(&amp;D)</translation>
    </message>
    <message>
        <source>Close the port; edits that were not written stay</source>
        <translation>关闭端口；尚未写入的修改会保留</translation>
    </message>
    <message>
        <source>Sc&amp;an bus…</source>
        <translation>扫描总线(&amp;A)…</translation>
    </message>
    <message>
        <source>Find controllers whose device id or baud rate is not known</source>
        <translation>查找设备 ID 或波特率未知的控制器</translation>
    </message>
    <message>
        <source>Cannot connect: %1.</source>
        <translation>无法连接：%1。</translation>
    </message>
    <message>
        <source>Could not connect to %1: %2</source>
        <translation>无法连接到 %1：%2</translation>
    </message>
    <message>
        <source>the built-in simulator</source>
        <translation>内置仿真器</translation>
    </message>
    <message>
        <source>Connected to the built-in simulator (%1).</source>
        <translation>已连接到内置仿真器（%1）。</translation>
    </message>
    <message>
        <source>Connected to %1.</source>
        <translation>已连接到 %1。</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>正在连接 %1…</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>未连接。</translation>
    </message>
    <message>
        <source>%1 is open, but the controller does not answer.</source>
        <translation>%1 已打开，但控制器没有应答。</translation>
    </message>
    <message>
        <source>%1 is open; waiting for the controller to answer…</source>
        <translation>%1 已打开；正在等待控制器应答…</translation>
    </message>
    <message>
        <source>Serial port plugged in: %1</source>
        <translation>插入了串口：%1</translation>
    </message>
    <message>
        <source>Network</source>
        <translation>网络</translation>
    </message>
    <message>
        <source>&amp;Protocol:</source>
        <translation>协议(&amp;P)：</translation>
    </message>
    <message>
        <source>Modbus TCP for a Modbus gateway; a transparent RS-485/Ethernet converter passes Modbus RTU frames (with CRC) over TCP, the default mode of most cheap converters</source>
        <translation>Modbus 网关用 Modbus TCP；透明模式的 RS-485/以太网转换器通过 TCP 原样传送 Modbus RTU 帧（带 CRC），这是大多数廉价转换器的默认模式</translation>
    </message>
    <message>
        <source>RS-485/Ethernet converter (transparent)</source>
        <translation>RS-485/以太网转换器（透明传输）</translation>
    </message>
    <message>
        <source>Line: %1</source>
        <translation>线路：%1</translation>
    </message>
    <message>
        <source>A controller simulated inside StepCom: nothing reaches real hardware.</source>
        <translation>在 StepCom 内部模拟的控制器：不会发送到真实硬件。</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlBusMonitor</name>
    <message>
        <source>link lost: %1</source>
        <translation>连接中断：%1</translation>
    </message>
    <message>
        <source>id %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>id %1: %2</source>
        <translation>ID %1：%2</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlLinkAdvice</name>
    <message>
        <source>not saved to flash: the built-in simulator starts its next run with the id and baud it saved (add --save-to-flash to keep them)</source>
        <translation>未保存到闪存：内置仿真器下次运行时使用它已保存的 ID 和波特率（加 --save-to-flash 可保留新设置）</translation>
    </message>
    <message>
        <source>not saved to flash: after the next power-off the controller answers at the id and baud it saved before (add --save-to-flash to keep them)</source>
        <translation>未保存到闪存：下次断电后，控制器将以之前保存的 ID 和波特率应答（加 --save-to-flash 可保留新设置）</translation>
    </message>
    <message>
        <source>the controller now speaks %1 baud on its RS-485 side: set the converter&apos;s (gateway&apos;s) serial side to %1 baud too, or it no longer reaches the controller</source>
        <translation>控制器的 RS-485 端现在使用 %1 波特：请把转换器（网关）的串口也设为 %1 波特，否则它将无法再连到控制器</translation>
    </message>
    <message>
        <source>next commands: stepcomctl %1 ...</source>
        <translation>后续命令：stepcomctl %1 ...</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlListen</name>
    <message>
        <source>stepcomctl: the port %1 was lost: %2</source>
        <translation>stepcomctl：端口 %1 已断开：%2</translation>
    </message>
    <message>
        <source>stepcomctl: cannot open %1 to listen: %2</source>
        <translation>stepcomctl：无法打开 %1 进行监听：%2</translation>
    </message>
    <message>
        <source>listening on %1 at %2 baud; nothing is sent (Ctrl-C ends)</source>
        <translation>正在 %1 上以 %2 波特率监听；不发送任何数据（Ctrl-C 结束）</translation>
    </message>
    <message>
        <source>adapter: %1</source>
        <translation>适配器：%1</translation>
    </message>
    <message>
        <source>heard %1 frames (%2 bytes): %3 pairs, %4 unanswered, %5 exceptions, %6 CRC errors (frames skipped), %7 stray bytes, %8 answers without their request</source>
        <translation>听到 %1 帧（%2 字节）：%3 对请求与应答，%4 个无应答，%5 个异常，%6 个 CRC 错误（帧已跳过），%7 个杂散字节，%8 个应答未听到其请求</translation>
    </message>
    <message>
        <source>id %1: %2 requests, %3 answered in %4-%5 ms (%6 ms on average), %7 unanswered</source>
        <translation>站号 %1：%2 个请求，%3 个在 %4-%5 ms 内应答（平均 %6 ms），%7 个无应答</translation>
    </message>
    <message>
        <source>id %1: %2 requests, none answered</source>
        <translation>站号 %1：%2 个请求，均无应答</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlMonitor</name>
    <message>
        <source>no sample was read: every poll failed (see the errors above)</source>
        <translation>没有读到任何样本：每次轮询都失败了（见上面的错误）</translation>
    </message>
    <message>
        <source>link lost: %1; trying again on its own (Ctrl-C ends)</source>
        <translation>连接丢失：%1；正在自动重试（按 Ctrl-C 结束）</translation>
    </message>
    <message numerus="yes">
        <source>link back at %1 after %n attempt(s)</source>
        <translation>
            <numerusform>连接已在 %1 恢复（尝试 %n 次）</numerusform>
        </translation>
    </message>
    <message>
        <source>; not saved to flash, lost: %1</source>
        <translation>；未保存到闪存而丢失的：%1</translation>
    </message>
    <message>
        <source>controller %1 restarted (power off?): positions and references lost%2%3</source>
        <translation>控制器 %1 重新启动了（断电？）：位置和参考点丢失%2%3</translation>
    </message>
    <message>
        <source>; seen: %1</source>
        <translation>；所见：%1</translation>
    </message>
    <message>
        <source>controller %1 may have restarted (power off?): it did not answer for %2 s and every axis reads 0 (%3); whether a motion ended there cannot be told: the references are not known, home again</source>
        <translation>控制器 %1 可能重新启动了（断电？）：它 %2 s 没有应答，现在所有轴都读到 0（%3）；无法判断是否只是运动停在那里：参考点未知，请重新回零</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlMotionWait</name>
    <message>
        <source>%1 would not move anything here (nothing in the homing order, or every motor runs): nothing to wait for</source>
        <translation>%1 在此不会使任何电机运动（回零顺序为空，或所有电机都在运行）：没有可等待的结果</translation>
    </message>
    <message>
        <source>%1: sent, waiting for the motion to end</source>
        <translation>%1：已发送，正在等待运动结束</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlOptions</name>
    <message>
        <source>Serial port of the controller (e.g. /dev/ttyUSB0, COM3).</source>
        <translation>控制器所连接的串口（例如 /dev/ttyUSB0、COM3）。</translation>
    </message>
    <message>
        <source>path</source>
        <translation>路径</translation>
    </message>
    <message>
        <source>Modbus TCP gateway or simulator, HOST[:PORT] (port 502).</source>
        <translation>Modbus TCP 网关或仿真器，格式为 主机[:端口]（默认端口 502）。</translation>
    </message>
    <message>
        <source>host:port</source>
        <translation>主机:端口</translation>
    </message>
    <message>
        <source>Baud rate: 4800, 9600, 19200 or 38400 (default 9600).</source>
        <translation>波特率：4800、9600、19200 或 38400（默认 9600）。</translation>
    </message>
    <message>
        <source>rate</source>
        <translation>波特率</translation>
    </message>
    <message>
        <source>parity</source>
        <translation>校验</translation>
    </message>
    <message>
        <source>Stop bits: 1 or 2 (default 1).</source>
        <translation>停止位：1 或 2（默认 1）。</translation>
    </message>
    <message>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <source>id</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Answer timeout in ms (default 500).</source>
        <translation>应答超时，单位 ms（默认 500）。</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Retries after a timeout (default 2).</source>
        <translation>超时后的重试次数（默认 2）。</translation>
    </message>
    <message>
        <source>Register map file to use instead of the built-in one.</source>
        <translation>使用指定的寄存器映射文件代替内置映射。</translation>
    </message>
    <message>
        <source>file</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>Show the Modbus traffic on standard error.</source>
        <translation>在标准错误输出上显示 Modbus 通信报文。</translation>
    </message>
    <message>
        <source>Do not ask: needed for commands that destroy settings.</source>
        <translation>不询问确认：执行会清除设置的命令时必须指定。</translation>
    </message>
    <message>
        <source>After writing, save the parameters to flash.</source>
        <translation>写入后将参数保存到闪存。</translation>
    </message>
    <message>
        <source>monitor: number of samples (default: until stopped).</source>
        <translation>monitor：采样次数（默认：一直采样到停止）。</translation>
    </message>
    <message>
        <source>monitor: ms between samples (default: as fast as the link allows).</source>
        <translation>monitor：采样间隔，单位 ms（默认：通信链路允许的最快速度）。</translation>
    </message>
    <message>
        <source>--tcp: &apos;%1&apos; is not HOST[:PORT]</source>
        <translation>--tcp：“%1”不符合 主机[:端口] 格式</translation>
    </message>
    <message>
        <source>--baud: &apos;%1&apos; is not a number</source>
        <translation>--baud：“%1”不是数字</translation>
    </message>
    <message>
        <source>--parity: &apos;%1&apos; is not none, even or odd</source>
        <translation>--parity：“%1”不是 none、even 或 odd</translation>
    </message>
    <message>
        <source>--stop-bits: &apos;%1&apos; is not 1 or 2</source>
        <translation>--stop-bits：“%1”不是 1 或 2</translation>
    </message>
    <message>
        <source>--timeout: &apos;%1&apos; is not a number</source>
        <translation>--timeout：“%1”不是数字</translation>
    </message>
    <message>
        <source>--retries: &apos;%1&apos; is not a number</source>
        <translation>--retries：“%1”不是数字</translation>
    </message>
    <message>
        <source>--count: &apos;%1&apos; is not a positive number</source>
        <translation>--count：“%1”不是正数</translation>
    </message>
    <message>
        <source>--interval: &apos;%1&apos; is not a number of ms</source>
        <translation>--interval：“%1”不是以 ms 为单位的数字</translation>
    </message>
    <message>
        <source>dump, apply: include the device id and baud (apply writes them only with this).</source>
        <translation>dump、apply：包括设备地址和波特率（apply 只有加此选项才写入它们）。</translation>
    </message>
    <message>
        <source>dump, report: name of the profile or the machine.</source>
        <translation>dump、report：参数文件或机器的名称。</translation>
    </message>
    <message>
        <source>text</source>
        <translation>文本</translation>
    </message>
    <message>
        <source>dump, report: notes to record.</source>
        <translation>dump、report：要记录的备注。</translation>
    </message>
    <message>
        <source>report: make the report from this profile file, not from a controller.</source>
        <translation>report：根据此参数文件生成报告，而不是读取控制器。</translation>
    </message>
    <message>
        <source>profile</source>
        <translation>参数文件</translation>
    </message>
    <message>
        <source>command: wait until a motion command ends and print how it ended (exit 0 only when done or referenced).</source>
        <translation>command：等待运动命令结束并输出其结果（仅在完成或已回零参考时退出码为 0）。</translation>
    </message>
    <message>
        <source>apply, command factory_reset/save_to_flash, write device.id/device.baud: do not save a backup of the controller&apos;s settings first.</source>
        <translation>apply、command factory_reset/save_to_flash、write device.id/device.baud：不先备份控制器参数。</translation>
    </message>
    <message>
        <source>move: a step of this many axis units (+ or -).</source>
        <translation>move：按此距离运行（轴单位，可正可负）。</translation>
    </message>
    <message>
        <source>distance</source>
        <translation>距离</translation>
    </message>
    <message>
        <source>--id: %1</source>
        <translation>--id：%1</translation>
    </message>
    <message>
        <source>--to: &apos;%1&apos; is not a device id 1-255</source>
        <translation>--to：“%1”不是 1-255 的设备 ID</translation>
    </message>
    <message>
        <source>move: to this position (axis units); assign-id: the new device id 1-255.</source>
        <translation>move：移动到此位置（轴单位）；assign-id：新的设备地址 1-255。</translation>
    </message>
    <message>
        <source>value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>RS-485/Ethernet converter in transparent mode: Modbus RTU frames over TCP, HOST:PORT.</source>
        <translation>透明模式的 RS-485/以太网转换器：通过 TCP 传送 Modbus RTU 帧，主机:端口。</translation>
    </message>
    <message>
        <source>Extra silence after an answer before the next request, for converters that need it (default 0).</source>
        <translation>收到应答后、发送下一个请求前额外的静默时间，供需要它的转换器使用（默认 0）。</translation>
    </message>
    <message>
        <source>give only one of --port, --tcp, --rtu-tcp and --sim</source>
        <translation>--port、--tcp、--rtu-tcp 和 --sim 只能给出一个</translation>
    </message>
    <message>
        <source>--rtu-tcp: &apos;%1&apos; is not HOST:PORT (converters have no standard port: see its settings page)</source>
        <translation>--rtu-tcp：“%1”不是 主机:端口（转换器没有标准端口：请查看它的设置页面）</translation>
    </message>
    <message>
        <source>--answer-delay: &apos;%1&apos; is not a number of ms</source>
        <translation>--answer-delay：“%1”不是毫秒数</translation>
    </message>
    <message>
        <source>--turnaround: &apos;%1&apos; is not a number of ms</source>
        <translation>--turnaround：“%1”不是毫秒数</translation>
    </message>
    <message>
        <source>--echo: Modbus TCP has no echo; it applies to --port and --rtu-tcp</source>
        <translation>--echo：Modbus TCP 没有回显；此选项用于 --port 和 --rtu-tcp</translation>
    </message>
    <message>
        <source>Device id 1-255 (default 1); several (1,2,3 or 1-3) for read, monitor, diff, apply, dump, report and command: each in turn on the one line, output keyed by id (report: one document).</source>
        <translation>设备 ID 1-255（默认 1）；read、monitor、diff、apply、dump、report 和 command 可给多个（1,2,3 或 1-3）：在同一条线路上依次执行，输出按 ID 分开（report：一份文档）。</translation>
    </message>
    <message>
        <source>Parity: none, even or odd (default none); scan: several, e.g. none,even,odd.</source>
        <translation>校验：none、even 或 odd（默认 none）；scan 可给多个，例如 none,even,odd。</translation>
    </message>
    <message>
        <source>scan: the baud rates to try, e.g. 9600,19200 (default all four, 9600 first); not over --tcp or --rtu-tcp, where the converter&apos;s line has its own.</source>
        <translation>scan：要尝试的波特率，例如 9600,19200（默认全部四种，先试 9600）；不适用于 --tcp 或 --rtu-tcp，那里转换器的串口有自己的波特率。</translation>
    </message>
    <message>
        <source>list</source>
        <translation>列表</translation>
    </message>
    <message>
        <source>scan: the device ids to try, e.g. 1-32 or 1,5,7 (default 1-247).</source>
        <translation>scan：要尝试的设备 ID，例如 1-32 或 1,5,7（默认 1-247）。</translation>
    </message>
    <message>
        <source>range</source>
        <translation>范围</translation>
    </message>
    <message>
        <source>scan: wait this long for each id&apos;s answer (default: fitted to the baud, 67 ms at 9600); more for controllers that answer slowly.</source>
        <translation>scan：每个 ID 等待应答的时间（默认按波特率自动，9600 时为 67 ms）；应答慢的控制器请设得更长。</translation>
    </message>
    <message>
        <source>--%1: over --tcp and --rtu-tcp the converter&apos;s serial line has its own baud and parity (set on the converter); the scan tries only ids there</source>
        <translation>--%1：使用 --tcp 和 --rtu-tcp 时，转换器的串口有自己的波特率和校验（在转换器上设定）；这时扫描只尝试 ID</translation>
    </message>
    <message>
        <source>--parity: &apos;%1&apos; is given twice</source>
        <translation>--parity：“%1” 重复给出</translation>
    </message>
    <message>
        <source>--parity: give one parity; several are for scan</source>
        <translation>--parity：请只给一种校验；多种校验只用于 scan</translation>
    </message>
    <message>
        <source>--%1 is an option of scan</source>
        <translation>--%1 是 scan 的选项</translation>
    </message>
    <message>
        <source>--bauds: &apos;%1&apos; is not one of %2</source>
        <translation>--bauds：“%1” 不是 %2 之一</translation>
    </message>
    <message>
        <source>--bauds: %1 is given twice</source>
        <translation>--bauds：%1 重复给出</translation>
    </message>
    <message>
        <source>--ids: %1</source>
        <translation>--ids：%1</translation>
    </message>
    <message>
        <source>--probe-timeout: &apos;%1&apos; is not a number of ms from 1 to 10000</source>
        <translation>--probe-timeout：“%1” 不是 1 到 10000 之间的毫秒数</translation>
    </message>
    <message>
        <source>The adapter echoes what it sends (half-duplex USB-RS485 adapters without echo suppression): skip the request&apos;s own bytes from the first request on (without it the echo is found by the first read and skipped from then on).</source>
        <translation>适配器会回显发送的数据（没有回显抑制的半双工 USB-RS485 适配器）：从第一个请求起跳过请求自身的字节（不加此选项时，第一次读取就会发现回显，此后跳过）。</translation>
    </message>
    <message>
        <source>How long the controller may take to answer: the least an adapted timeout allows (default 35, the manual&apos;s). Answers are judged by what they say, whenever they come.</source>
        <translation>控制器可能需要多长时间应答：自适应超时的下限（默认 35，即说明书的值）。无论应答何时到达，都按其内容判断。</translation>
    </message>
    <message>
        <source>Always wait --timeout for an answer, instead of fitting the timeout to the controller&apos;s measured answers (4x the median, at most --timeout).</source>
        <translation>总是等待完整的 --timeout，而不是按测得的控制器应答时间调整超时（中位数的 4 倍，最多 --timeout）。</translation>
    </message>
    <message>
        <source>Append the session log of this run (every frame, with its time) to this file; stepcomctl replay reads it.</source>
        <translation>将本次运行的会话日志（每一帧及其时间）追加到此文件；stepcomctl replay 可读取它。</translation>
    </message>
    <message>
        <source>replay: list what happened (time, device, what).</source>
        <translation>replay：列出发生的事情（时间、设备、内容）。</translation>
    </message>
    <message>
        <source>replay: the state of every device at TIME: seconds from the log&apos;s start or a clock time hh:mm:ss[.mmm].</source>
        <translation>replay：每台设备在 TIME 时刻的状态：距日志开始的秒数或钟点时间 hh:mm:ss[.mmm]。</translation>
    </message>
    <message>
        <source>time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>replay: what changed from T1 to the time after it (--diff T1 T2).</source>
        <translation>replay：从 T1 到其后时间的变化（--diff T1 T2）。</translation>
    </message>
    <message>
        <source>T1</source>
        <translation>T1</translation>
    </message>
    <message>
        <source>replay of a support bundle: the log inside to replay (default: the newest).</source>
        <translation>回放支持包：要回放的包内日志（默认：最新的）。</translation>
    </message>
    <message>
        <source>name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>bundle: the session logs of the last N days (default 7).</source>
        <translation>bundle：最近 N 天的会话日志（默认 7）。</translation>
    </message>
    <message>
        <source>bundle: the profile (and its checklist) to add.</source>
        <translation>bundle：要加入的参数文件（及其调试清单）。</translation>
    </message>
    <message>
        <source>--days: &apos;%1&apos; is not a number of days</source>
        <translation>--days：“%1”不是天数</translation>
    </message>
    <message>
        <source>Use the built-in simulated controller (it keeps what it saved to flash between runs).</source>
        <translation>使用内置仿真控制器（它在多次运行之间保留已保存到闪存的内容）。</translation>
    </message>
    <message>
        <source>Start the built-in simulator from the factory again (id 1, 9600 baud): forget what it saved to flash. Alone, or before a --sim command.</source>
        <translation>让内置仿真器恢复出厂状态（ID 1，9600 波特）：清除它保存到闪存的内容。可单独使用，或用在 --sim 命令之前。</translation>
    </message>
    <message>
        <source>--baud: &apos;%1&apos; is not 4800, 9600, 19200 or 38400</source>
        <translation>--baud：“%1”不是 4800、9600、19200 或 38400</translation>
    </message>
    <message>
        <source>listen: stop after N seconds (default: until Ctrl-C).</source>
        <translation>listen：N 秒后停止（默认：直到 Ctrl-C）。</translation>
    </message>
    <message>
        <source>Who switches an RS-485 adapter&apos;s direction: auto (the adapter itself, default), kernel (the driver&apos;s RS-485 mode, RTS on send) or rts (StepCom raises RTS for each request).</source>
        <translation>由谁切换 RS-485 适配器的收发方向：auto（适配器自己，默认）、kernel（驱动的 RS-485 模式，发送时置 RTS）或 rts（StepCom 为每个请求拉高 RTS）。</translation>
    </message>
    <message>
        <source>mode</source>
        <translation>模式</translation>
    </message>
    <message>
        <source>--rs485 kernel: the delays before and after sending, in us (default 0,0).</source>
        <translation>--rs485 kernel：发送前后的延时，单位 us（默认 0,0）。</translation>
    </message>
    <message>
        <source>before,after</source>
        <translation>前,后</translation>
    </message>
    <message>
        <source>--rs485: &apos;%1&apos; is not auto, kernel or rts</source>
        <translation>--rs485：“%1”不是 auto、kernel 或 rts</translation>
    </message>
    <message>
        <source>--rs485-delays: &apos;%1&apos; is not BEFORE,AFTER in us (e.g. 0,500)</source>
        <translation>--rs485-delays：“%1”不是以 us 为单位的 前,后（例如 0,500）</translation>
    </message>
    <message>
        <source>--seconds: &apos;%1&apos; is not a positive number of seconds</source>
        <translation>--seconds：“%1”不是正的秒数</translation>
    </message>
    <message>
        <source>Machine-readable JSON: one object, exit, result and errors, for every command and usage error (monitor, listen: its last line).</source>
        <translation>机器可读的 JSON：每个命令和用法错误都输出一个对象，含 exit、result 和 errors（monitor、listen：最后一行）。</translation>
    </message>
    <message>
        <source>no command given (%1)</source>
        <translation>未给出命令（%1）</translation>
    </message>
    <message>
        <source>--cycles: &apos;%1&apos; is not a positive number</source>
        <translation>--cycles：“%1”不是正数</translation>
    </message>
    <message>
        <source>run: how many times the whole step list runs (default 1); lost-steps, backlash: back-and-forth moves (default 3); margin: at each value (default 2).</source>
        <translation>run：整个步骤表运行的次数（默认 1）；lost-steps、backlash：往返移动的次数（默认 3）；margin：每个值下的次数（默认 2）。</translation>
    </message>
    <message>
        <source>lost-steps, margin: each move of the test (default 10 axis units); backlash: each move (default 1).</source>
        <translation>lost-steps、margin：测试中每次移动的距离（默认 10 个轴单位）；backlash：每次移动的距离（默认 1）。</translation>
    </message>
    <message>
        <source>d</source>
        <translation>距离</translation>
    </message>
    <message>
        <source>margin: the step between the values tested.</source>
        <translation>margin：所测试的值之间的步长。</translation>
    </message>
    <message>
        <source>margin: search the acceleration register at the motor&apos;s own speed.</source>
        <translation>margin：在电机自身的转速下搜索加速度寄存器。</translation>
    </message>
    <message>
        <source>margin: write the recommended value, reviewed as write reviews it.</source>
        <translation>margin：写入推荐值，并像 write 一样先经过审查。</translation>
    </message>
    <message>
        <source>run: after the cycles, the lost-step test on every axis the sequence moved.</source>
        <translation>run：循环结束后，对序列移动过的每根轴运行丢步测试。</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlRunner</name>
    <message>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>no controller given: use --port PATH, --tcp HOST[:PORT] or --sim</source>
        <translation>未指定控制器：请使用 --port 路径、--tcp 主机[:端口] 或 --sim</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>无法连接到 %1：%2</translation>
    </message>
    <message>
        <source>cannot start the built-in simulator: %1</source>
        <translation>无法启动内置仿真器：%1</translation>
    </message>
    <message>
        <source>unknown parameter &apos;%1&apos; (see: stepcomctl params)</source>
        <translation>未知参数“%1”（参见：stepcomctl params）</translation>
    </message>
    <message>
        <source>%1 is a command and cannot be read</source>
        <translation>%1 是命令，不能读取</translation>
    </message>
    <message>
        <source>write needs KEY=VALUE arguments</source>
        <translation>write 需要 参数名=值 形式的参数</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not KEY=VALUE</source>
        <translation>“%1”不符合 参数名=值 格式</translation>
    </message>
    <message>
        <source>%1 is a command: use &apos;stepcomctl command %1&apos;</source>
        <translation>%1 是命令：请使用“stepcomctl command %1”</translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 为只读参数</translation>
    </message>
    <message>
        <source>nothing was written</source>
        <translation>未写入任何参数</translation>
    </message>
    <message>
        <source>(written, verified)</source>
        <translation>（已写入并验证）</translation>
    </message>
    <message>
        <source>not written: %1</source>
        <translation>未写入：%1</translation>
    </message>
    <message>
        <source>this map has no save_to_flash command</source>
        <translation>此寄存器映射中没有 save_to_flash 命令</translation>
    </message>
    <message>
        <source>saved to flash</source>
        <translation>已保存到闪存</translation>
    </message>
    <message>
        <source>command needs exactly one command name (see: stepcomctl params)</source>
        <translation>command 需要且只能有一个命令名（参见：stepcomctl params）</translation>
    </message>
    <message>
        <source>%1 is a parameter, not a command: use read or write</source>
        <translation>%1 是参数而不是命令：请使用 read 或 write</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos; (see: stepcomctl params)</source>
        <translation>未知命令“%1”（参见：stepcomctl params）</translation>
    </message>
    <message>
        <source>%1 destroys settings (%2); add --yes if you mean it</source>
        <translation>%1 会清除设置（%2）；确定要执行请加上 --yes</translation>
    </message>
    <message>
        <source>%1: done</source>
        <translation>%1：完成</translation>
    </message>
    <message>
        <source>monitor takes no arguments, only --count and --interval</source>
        <translation>monitor 不接受参数，只能使用 --count 和 --interval 选项</translation>
    </message>
    <message>
        <source>%1 needs exactly one profile file</source>
        <translation>%1 需要且只需要一个参数文件</translation>
    </message>
    <message>
        <source>dump needs exactly one file to write the profile to</source>
        <translation>dump 需要且只需要一个用于保存参数的文件</translation>
    </message>
    <message>
        <source>nothing was saved: the controller could not be read completely</source>
        <translation>未保存任何内容：无法完整读取控制器</translation>
    </message>
    <message numerus="yes">
        <source>saved %n parameter(s) of %1 to %2</source>
        <translation>
            <numerusform>已将 %1 的 %n 个参数保存到 %2</numerusform>
        </translation>
    </message>
    <message>
        <source>the controller holds every value of the profile</source>
        <translation>控制器中的值与参数文件完全一致</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) differ (controller -&gt; profile)</source>
        <translation>
            <numerusform>%n 个值不同（控制器 -&gt; 参数文件）</numerusform>
        </translation>
    </message>
    <message>
        <source>note: device.baud changes the controller&apos;s serial side only</source>
        <translation>注意：device.baud 只改变控制器串口一侧</translation>
    </message>
    <message>
        <source>not applied (needs --include-link): %1</source>
        <translation>未应用（需要 --include-link）：%1</translation>
    </message>
    <message>
        <source>will write %1</source>
        <translation>将写入 %1</translation>
    </message>
    <message>
        <source>the controller already holds the profile&apos;s values</source>
        <translation>控制器中已是参数文件的值</translation>
    </message>
    <message numerus="yes">
        <source>Write these %n value(s) to the controller? [y/N] </source>
        <translation>
            <numerusform>将这 %n 个值写入控制器吗？[y/N] </numerusform>
        </translation>
    </message>
    <message>
        <source>not confirmed: nothing was written</source>
        <translation>未确认：未写入任何内容</translation>
    </message>
    <message>
        <source>no answer on standard input: nothing was written (use --yes)</source>
        <translation>标准输入没有回答：未写入任何内容（可使用 --yes）</translation>
    </message>
    <message>
        <source>not saved to flash: the controller forgets these values at power-off (use --save-to-flash)</source>
        <translation>未保存到闪存：控制器断电后会丢失这些值（可使用 --save-to-flash）</translation>
    </message>
    <message>
        <source>report needs exactly one file (.pdf or .html)</source>
        <translation>report 需要且只需要一个文件（.pdf 或 .html）</translation>
    </message>
    <message>
        <source>%1: the report is written as .pdf or .html</source>
        <translation>%1：报告只能保存为 .pdf 或 .html</translation>
    </message>
    <message>
        <source>no report: the controller could not be read completely</source>
        <translation>未生成报告：无法完整读取控制器</translation>
    </message>
    <message>
        <source>report written to %1</source>
        <translation>报告已写入 %1</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos; (%2)</source>
        <translation>未知命令 &apos;%1&apos;（%2）</translation>
    </message>
    <message>
        <source>diff needs one profile file (compared with the controller) or two (compared with each other)</source>
        <translation>diff 需要一个参数文件（与控制器比较）或两个参数文件（互相比较）</translation>
    </message>
    <message>
        <source>left out of the comparison:</source>
        <translation>未参与比较：</translation>
    </message>
    <message numerus="yes">
        <source>the controller holds every value both maps have; %n left out</source>
        <translation>
            <numerusform>控制器中已是两个寄存器表共有的全部值；%n 个值未参与比较</numerusform>
        </translation>
    </message>
    <message>
        <source>nothing was compared</source>
        <translation>未进行任何比较</translation>
    </message>
    <message>
        <source>A = %1: &quot;%2&quot;, register map %3</source>
        <translation>A = %1：“%2”，寄存器表 %3</translation>
    </message>
    <message>
        <source>B = %1: &quot;%2&quot;, register map %3</source>
        <translation>B = %1：“%2”，寄存器表 %3</translation>
    </message>
    <message>
        <source>differ (A -&gt; B):</source>
        <translation>不同（A -&gt; B）：</translation>
    </message>
    <message>
        <source>only in A (%1):</source>
        <translation>只在 A 中（%1）：</translation>
    </message>
    <message>
        <source>only in B (%1):</source>
        <translation>只在 B 中（%1）：</translation>
    </message>
    <message>
        <source>not settings of register map %1, or out of its range (as the files hold them, A -&gt; B):</source>
        <translation>不是寄存器表 %1 的设置参数，或超出其范围（按文件中的原值，A -&gt; B）：</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <source>the two profiles hold the same values</source>
        <translation>两个参数文件的值完全相同</translation>
    </message>
    <message>
        <source>%1 differ, %2 only in A, %3 only in B, %4 outside this map</source>
        <translation>%1 个不同，%2 个只在 A 中，%3 个只在 B 中，%4 个超出此寄存器表</translation>
    </message>
    <message>
        <source>not applied:</source>
        <translation>不应用：</translation>
    </message>
    <message>
        <source>the profile holds no setting of this map: nothing to apply</source>
        <translation>参数文件中没有此寄存器表的任何设置参数：无可应用</translation>
    </message>
    <message>
        <source>the controller already holds every value both maps have</source>
        <translation>控制器中已是两个寄存器表共有的全部值</translation>
    </message>
    <message>
        <source>no report: %1 is not a profile StepCom can read</source>
        <translation>未生成报告：%1 不是 StepCom 可读取的参数文件</translation>
    </message>
    <message>
        <source>not in the report:</source>
        <translation>报告中未包含：</translation>
    </message>
    <message>
        <source>report written to %1, made from the profile file %2 (no controller was read)</source>
        <translation>报告已写入 %1，根据参数文件 %2 生成（未读取控制器）</translation>
    </message>
    <message>
        <source>no backup of the controller&apos;s settings could be saved (%1): nothing was written (--no-backup applies without one)</source>
        <translation>无法保存控制器设置的备份（%1）：未写入任何值（--no-backup 可在不备份的情况下应用）</translation>
    </message>
    <message>
        <source>backup of the controller&apos;s settings: %1</source>
        <translation>控制器设置的备份：%1</translation>
    </message>
    <message>
        <source>no report: the checklist beside the profile cannot be read</source>
        <translation>未生成报告：无法读取参数文件旁的检查表</translation>
    </message>
    <message>
        <source>with the commissioning checklist %1: %2</source>
        <translation>包含调试检查表 %1：%2</translation>
    </message>
    <message>
        <source>%1: sent (add --wait to wait for how it ends)</source>
        <translation>%1：已发送（加 --wait 可等待其结果）</translation>
    </message>
    <message>
        <source>--wait: %1 has no end to wait for (single move, home, home in order, return to data zero, arc and line have one)</source>
        <translation>--wait：%1 没有可等待的结束（单次运动、回零、按顺序回零、回数据零点、圆弧和直线才有）</translation>
    </message>
    <message>
        <source>no backup of the controller&apos;s settings could be saved (%1): nothing was done (--no-backup goes on without one)</source>
        <translation>无法保存控制器参数的备份（%1）：未执行任何操作（--no-backup 可不备份继续）</translation>
    </message>
    <message>
        <source>move needs one motor: move motor1 --by D or --to X</source>
        <translation>move 需要一个电机：move motor1 --by D 或 --to X</translation>
    </message>
    <message>
        <source>there is no motor %1 (this map has motor1 .. motor%2)</source>
        <translation>没有电机 %1（此寄存器表有 motor1 .. motor%2）</translation>
    </message>
    <message>
        <source>move needs exactly one of --by D and --to X</source>
        <translation>move 需要且只需要 --by D 和 --to X 之一</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1：“%2”不是数字</translation>
    </message>
    <message>
        <source>id %1: %2</source>
        <translation>ID %1：%2</translation>
    </message>
    <message>
        <source>== device id %1 ==</source>
        <translation>== 设备 ID %1 ==</translation>
    </message>
    <message>
        <source>assign-id: give the new id with --to N, and one --id (the id the controller answers at now, 1 from the factory)</source>
        <translation>assign-id：用 --to N 给出新 ID，并给一个 --id（控制器当前应答的 ID，出厂为 1）</translation>
    </message>
    <message>
        <source>assign-id: the controller already has id %1</source>
        <translation>assign-id：控制器已经是 ID %1</translation>
    </message>
    <message>
        <source>link: %1</source>
        <translation>链路：%1</translation>
    </message>
    <message>
        <source>saved the settings of %1 to %2</source>
        <translation>已将 %1 的设置保存到 %2</translation>
    </message>
    <message>
        <source>report --from makes the report of one profile file: give one --id</source>
        <translation>report --from 只根据一个参数文件生成报告：请只给一个 --id</translation>
    </message>
    <message>
        <source>no report: not every controller could be read completely</source>
        <translation>未生成报告：并非每台控制器都能完整读取</translation>
    </message>
    <message numerus="yes">
        <source>report of %n controller(s) written to %1</source>
        <translation>
            <numerusform>已将 %n 台控制器的报告写入 %1</numerusform>
        </translation>
    </message>
    <message>
        <source>not supported by this controller (left out): %1</source>
        <translation>此控制器不支持（已排除）：%1</translation>
    </message>
    <message>
        <source>nothing was saved: %1</source>
        <translation>未保存任何内容：%1</translation>
    </message>
    <message numerus="yes">
        <source>Write these %n value(s) to id %1? [y/N] </source>
        <translation>
            <numerusform>向 ID %1 写入这 %n 个值？[y/N] </numerusform>
        </translation>
    </message>
    <message>
        <source>note: %1</source>
        <translation>注意：%1</translation>
    </message>
    <message>
        <source>%1 is not supported by this controller</source>
        <translation>此控制器不支持 %1</translation>
    </message>
    <message>
        <source>scan takes no arguments (&apos;%1&apos;): give --bauds, --parity and --ids</source>
        <translation>scan 不接受参数（“%1”）：请用 --bauds、--parity 和 --ids</translation>
    </message>
    <message>
        <source>replay needs a log and one of --events, --at TIME or --diff T1 T2</source>
        <translation>replay 需要一个日志以及 --events、--at TIME 或 --diff T1 T2 之一</translation>
    </message>
    <message>
        <source>--entry: the bundle holds no log %1 (it holds: %2)</source>
        <translation>--entry：支持包中没有日志 %1（其中有：%2）</translation>
    </message>
    <message>
        <source>replaying %1 (logs in the bundle: %2; --entry NAME for another)</source>
        <translation>正在回放 %1（支持包中的日志数：%2；用 --entry NAME 选择其他日志）</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <source>at %1, link %2</source>
        <translation>在 %1，链路%2</translation>
    </message>
    <message>
        <source>up</source>
        <translation>已连接</translation>
    </message>
    <message>
        <source>down</source>
        <translation>已断开</translation>
    </message>
    <message>
        <source>answering</source>
        <translation>有应答</translation>
    </message>
    <message>
        <source>not answering</source>
        <translation>无应答</translation>
    </message>
    <message>
        <source>last error at %1: %2</source>
        <translation>最后的错误在 %1：%2</translation>
    </message>
    <message>
        <source>(last written: %1)</source>
        <translation>（最后写入：%1）</translation>
    </message>
    <message>
        <source>from %1 to %2, changes: %3</source>
        <translation>从 %1 到 %2，变化数：%3</translation>
    </message>
    <message>
        <source>bundle needs the name of the zip file to write</source>
        <translation>bundle 需要要写入的 zip 文件名</translation>
    </message>
    <message>
        <source>wrote %1 (%2):</source>
        <translation>已写入 %1（%2）：</translation>
    </message>
    <message>
        <source>%1: give one device id; several ids work with read, monitor, diff, apply, dump, report, bundle and command (without --wait)</source>
        <translation>%1：请只给一个设备 ID；多个 ID 只适用于 read、monitor、diff、apply、dump、report、bundle 和 command（不带 --wait）</translation>
    </message>
    <message>
        <source>--profile: %1 does not exist</source>
        <translation>--profile：%1 不存在</translation>
    </message>
    <message>
        <source>the profile goes into the bundle as it is, but not into the report</source>
        <translation>参数文件按原样放入支持包，但不进入报告</translation>
    </message>
    <message>
        <source>no bundle: not every controller could be read completely (without --port, --tcp or --sim the bundle has no controller in its report)</source>
        <translation>未生成支持包：并非每台控制器都能完整读取（不加 --port、--tcp 或 --sim 时，支持包的报告中不含控制器）</translation>
    </message>
    <message>
        <source>no machine report: no controller was read (--port, --tcp or --sim) and no profile was given (--profile)</source>
        <translation>无整机报告：未读取任何控制器（--port、--tcp 或 --sim），也未给出参数文件（--profile）</translation>
    </message>
    <message>
        <source>check: %1</source>
        <translation>请确认：%1</translation>
    </message>
    <message>
        <source>nothing was written: the window asks before writing these values; add --yes to write them anyway</source>
        <translation>未写入任何值：窗口写入这些值前会先询问；确定要写入请加 --yes</translation>
    </message>
    <message>
        <source>what the values are checked against could not be read: nothing was written</source>
        <translation>无法读取用于检查这些值的参数：未写入任何值</translation>
    </message>
    <message>
        <source>%1: %2 has more decimals than motor %3 counts in (steps of %4 %5): nothing was moved</source>
        <translation>%1：%2 的小数位多于电机 %3 的计数精度（步长 %4 %5）：未运行</translation>
    </message>
    <message numerus="yes">
        <source>(the same for %n more read(s) of this command)</source>
        <translation>
            <numerusform>（本命令另有 %n 次读取得到相同结果）</numerusform>
        </translation>
    </message>
    <message>
        <source>next commands: stepcomctl %1 ...</source>
        <translation>后续命令：stepcomctl %1 ...</translation>
    </message>
    <message>
        <source>id %1 lasts until the power is switched off, then the controller answers at the id in its flash again (id 1 from the factory); add --save-to-flash to keep it</source>
        <translation>ID %1 只保持到断电为止，之后控制器将重新以闪存中的 ID 应答（出厂为 ID 1）；加 --save-to-flash 可保留它</translation>
    </message>
    <message>
        <source>scan: give the line to scan: --port, --rtu-tcp, --tcp or --sim</source>
        <translation>scan：请给出要扫描的线路：--port、--rtu-tcp、--tcp 或 --sim</translation>
    </message>
    <message>
        <source>it has no serial line here</source>
        <translation>它在这里没有串行线路</translation>
    </message>
    <message>
        <source>ports takes no arguments (&apos;%1&apos;)</source>
        <translation>ports 不带参数（“%1”）</translation>
    </message>
    <message>
        <source>no serial port found: is the USB adapter plugged in? (its driver&apos;s messages: sudo dmesg | tail)</source>
        <translation>未找到串口：USB 适配器插好了吗？（驱动信息：sudo dmesg | tail）</translation>
    </message>
    <message>
        <source>S/N %1</source>
        <translation>序列号 %1</translation>
    </message>
    <message>
        <source>stable name: %1</source>
        <translation>固定名称：%1</translation>
    </message>
    <message>
        <source>no permission to open it: add yourself to its group (ls -l %1; usually dialout), then log in again</source>
        <translation>没有打开它的权限：请把自己加入它所属的组（ls -l %1；通常为 dialout），然后重新登录</translation>
    </message>
    <message>
        <source>open it with: stepcomctl --port %1 read device.id</source>
        <translation>打开方式：stepcomctl --port %1 read device.id</translation>
    </message>
    <message>
        <source>listen takes no arguments, only --port, --baud, --parity, --seconds, --json and --log</source>
        <translation>listen 不带参数，只接受 --port、--baud、--parity、--seconds、--json 和 --log</translation>
    </message>
    <message>
        <source>listen hears a serial line: give --port (a line StepCom does not drive; --tcp and --sim have no other master to hear)</source>
        <translation>listen 监听串口线路：请给出 --port（一条不由 StepCom 驱动的线路；--tcp 和 --sim 上没有其他主站可听）</translation>
    </message>
    <message>
        <source>%1 (at %2)</source>
        <translation>%1（在 %2）</translation>
    </message>
    <message>
        <source>cycles done: %1; cycle time min %2 s, median %3 s, max %4 s; %5 s in all</source>
        <translation>完成循环：%1；循环时间最短 %2 秒，中位 %3 秒，最长 %4 秒；共 %5 秒</translation>
    </message>
    <message>
        <source>cycle %1 %2: %3</source>
        <translation>循环 %1 %2：%3</translation>
    </message>
    <message>
        <source>cycle %1 done in %2 s</source>
        <translation>循环 %1 用时 %2 秒完成</translation>
    </message>
    <message>
        <source>the run could not start: not connected</source>
        <translation>无法开始运行：未连接</translation>
    </message>
    <message>
        <source>run needs one sequence file: run FILE</source>
        <translation>run 需要一个序列文件：run 文件</translation>
    </message>
    <message>
        <source>the sequence file was refused: nothing was sent</source>
        <translation>序列文件被拒绝：未发送任何内容</translation>
    </message>
    <message>
        <source>Run it? The machine will move. [y/N] </source>
        <translation>运行吗？机器将会运动。[y/N] </translation>
    </message>
    <message>
        <source>not confirmed: nothing was sent</source>
        <translation>未确认：未发送任何内容</translation>
    </message>
    <message>
        <source>no answer on standard input: nothing was sent (use --yes)</source>
        <translation>标准输入没有回答：未发送任何内容（请用 --yes）</translation>
    </message>
    <message>
        <source>%1 needs one motor: %1 motorN (N from 1 to %2)</source>
        <translation>%1 需要一个电机：%1 motorN（N 为 1 到 %2）</translation>
    </message>
    <message>
        <source>--distance: &apos;%1&apos; is not a positive distance</source>
        <translation>--distance：“%1”不是正的距离</translation>
    </message>
    <message>
        <source>--%1: &apos;%2&apos; is not a positive whole number</source>
        <translation>--%1：“%2”不是正整数</translation>
    </message>
    <message>
        <source>Run it? The axis will move. [y/N] </source>
        <translation>运行吗？轴将会运动。[y/N] </translation>
    </message>
    <message>
        <source>no answer on standard input: nothing was moved (use --yes)</source>
        <translation>标准输入没有回答：没有运动（请用 --yes）</translation>
    </message>
    <message>
        <source>not confirmed: nothing was moved</source>
        <translation>未确认：没有运动</translation>
    </message>
    <message>
        <source>--apply: nothing kept its steps, nothing was written</source>
        <translation>--apply：没有未丢步的值，未写入任何内容</translation>
    </message>
    <message>
        <source>%1, %2: gauge (mm)? </source>
        <translation>%1，%2：百分表读数 gauge (mm)? </translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number: type the gauge&apos;s reading</source>
        <translation>“%1”不是数字：请输入百分表的读数</translation>
    </message>
    <message>
        <source>check-steps: %1</source>
        <translation>check-steps：%1</translation>
    </message>
</context>
<context>
    <name>stepcom::CtlScan</name>
    <message numerus="yes">
        <source>scanning %1: %n id(s), %2 ms a probe</source>
        <translation>
            <numerusform>正在扫描 %1：%n 个 ID，每次探测 %2 ms</numerusform>
        </translation>
    </message>
    <message>
        <source>found %1</source>
        <translation>找到 %1</translation>
    </message>
    <message>
        <source>over a network the converter&apos;s or gateway&apos;s serial line has its own baud and parity: only the ids are scanned</source>
        <translation>经网络扫描时，转换器或网关的串口有自己的波特率和校验：只扫描 ID</translation>
    </message>
    <message>
        <source>at most about %1 s when nobody answers; a scan only reads</source>
        <translation>无人应答时最多约 %1 s；扫描只读取</translation>
    </message>
    <message>
        <source>%1 of %2 probed (id %3)</source>
        <translation>已探测 %1/%2（ID %3）</translation>
    </message>
    <message>
        <source>scan stopped: %1</source>
        <translation>扫描已停止：%1</translation>
    </message>
    <message numerus="yes">
        <source>%n controller(s) found in %1 s</source>
        <translation>
            <numerusform>%1 s 内找到 %n 台控制器</numerusform>
        </translation>
    </message>
    <message>
        <source>No controller answered. Check the power, the wiring (A and B swapped?), the port, and for a controller that answers slowly give --probe-timeout.</source>
        <translation>没有控制器应答。请检查电源、接线（A、B 接反？）和端口；控制器应答慢时请给出 --probe-timeout。</translation>
    </message>
    <message>
        <source>id</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>baud</source>
        <translation>波特率</translation>
    </message>
    <message>
        <source>parity</source>
        <translation>校验</translation>
    </message>
    <message>
        <source>answer</source>
        <translation>应答</translation>
    </message>
    <message>
        <source>controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>id %1 answered after %2 ms, later than the probe waited: connect with --timeout %3</source>
        <translation>ID %1 在 %2 ms 后才应答，晚于探测等待的时间：连接时请用 --timeout %3</translation>
    </message>
</context>
<context>
    <name>stepcom::DerivedValues</name>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 min %2 s</translation>
    </message>
    <message>
        <source>%1 h %2 min</source>
        <translation>%1 h %2 min</translation>
    </message>
    <message>
        <source>Pulses per revolution:</source>
        <translation>每转脉冲数：</translation>
    </message>
    <message>
        <source>Pulse rate at the set speed:</source>
        <translation>设定速度下的脉冲频率：</translation>
    </message>
    <message>
        <source>Linear speed:</source>
        <translation>线速度：</translation>
    </message>
    <message>
        <source>Revolutions per move:</source>
        <translation>单次运行圈数：</translation>
    </message>
    <message>
        <source>Pulses per move:</source>
        <translation>单次运行脉冲数：</translation>
    </message>
    <message>
        <source>Ramp to the set speed:</source>
        <translation>加速到设定速度用时：</translation>
    </message>
    <message>
        <source>Estimated move time:</source>
        <translation>单次运行预计用时：</translation>
    </message>
    <message>
        <source>360 / step angle × microsteps</source>
        <translation>360 / 步距角 × 细分</translation>
    </message>
    <message>
        <source>Speed (rpm) × pulses per revolution / 60: what the driver must accept</source>
        <translation>速度 (rpm) × 每转脉冲数 / 60：驱动器必须能接收的脉冲频率</translation>
    </message>
    <message>
        <source>Speed (rpm) × pitch / 60</source>
        <translation>速度 (rpm) × 螺距 / 60</translation>
    </message>
    <message>
        <source>Speed (rpm) × pitch</source>
        <translation>速度 (rpm) × 螺距</translation>
    </message>
    <message>
        <source>Move distance / pitch</source>
        <translation>单次运行距离 / 螺距</translation>
    </message>
    <message>
        <source>Move distance / pitch × pulses per revolution, in whole pulses as the controller sends them</source>
        <translation>单次运行距离 / 螺距 × 每转脉冲数，按控制器实际发出的整数个脉冲计算</translation>
    </message>
    <message>
        <source>(Pulse rate − start frequency) / accel/decel frequency: the rate rises by the accel/decel frequency every millisecond; braking takes as long</source>
        <translation>（脉冲频率 − 启动频率）/ 加减频率：频率每毫秒升高一个加减频率值；减速所需时间相同</translation>
    </message>
    <message>
        <source>A single move with its ramps up and down, as the simulator runs it (start frequency, accel/decel frequency per millisecond, speed)</source>
        <translation>按仿真器的运行方式估算一次单次运行（含加速和减速）的时间（启动频率、每毫秒的加减频率、速度）</translation>
    </message>
    <message>
        <source>units</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>%1 pulses/rev</source>
        <translation>%1 脉冲/转</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>%1 %2/s</source>
        <translation>%1 %2/s</translation>
    </message>
    <message>
        <source>%1 %2/min</source>
        <translation>%1 %2/min</translation>
    </message>
    <message>
        <source>%1 rev</source>
        <translation>%1 圈</translation>
    </message>
    <message>
        <source>%1 pulses</source>
        <translation>%1 个脉冲</translation>
    </message>
    <message>
        <source>none (start frequency ≥ pulse rate)</source>
        <translation>无（启动频率 ≥ 脉冲频率）</translation>
    </message>
</context>
<context>
    <name>stepcom::DeviceClient</name>
    <message>
        <source>nothing readable among the parameters asked for</source>
        <translation>所请求的参数中没有可读取的参数</translation>
    </message>
    <message>
        <source>read block %1/%2</source>
        <translation>读取数据块 %1/%2</translation>
    </message>
    <message>
        <source>unknown parameter</source>
        <translation>未知参数</translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 为只读参数</translation>
    </message>
    <message>
        <source>%1 is given twice</source>
        <translation>%1 被指定了两次</translation>
    </message>
    <message>
        <source>could not reopen the port at the new baud: %1</source>
        <translation>无法以新波特率重新打开端口：%1</translation>
    </message>
    <message>
        <source>%1: wrote %2 but the controller holds %3</source>
        <translation>%1：已写入 %2，但控制器中的值为 %3</translation>
    </message>
    <message>
        <source>%1: wrote %2 but could not read it back</source>
        <translation>%1：已写入 %2，但无法回读</translation>
    </message>
</context>
<context>
    <name>stepcom::DeviceListDock</name>
    <message>
        <source>Device id %1 is already on the list.</source>
        <translation>设备 ID %1 已在列表中。</translation>
    </message>
    <message>
        <source>Devices on the line</source>
        <translation>总线上的设备</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Referenced</source>
        <translation>参考点</translation>
    </message>
    <message>
        <source>Errors</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>Add device</source>
        <translation>添加设备</translation>
    </message>
    <message>
        <source>Device id to add</source>
        <translation>要添加的设备 ID</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>answering (in view)</source>
        <translation>应答中（当前显示）</translation>
    </message>
    <message>
        <source>not answering (in view)</source>
        <translation>无应答（当前显示）</translation>
    </message>
    <message>
        <source>asking (in view)</source>
        <translation>询问中（当前显示）</translation>
    </message>
    <message>
        <source>answering</source>
        <translation>应答中</translation>
    </message>
    <message>
        <source>not answering</source>
        <translation>无应答</translation>
    </message>
    <message>
        <source>asking</source>
        <translation>询问中</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>no</source>
        <translation>无</translation>
    </message>
    <message>
        <source>motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>Device ids are 1 to 255, not %1.</source>
        <translation>设备 ID 为 1 到 255，不能是 %1。</translation>
    </message>
    <message>
        <source>Other devices read every:</source>
        <translation>其他设备读取间隔：</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>The device in view is read at the live rate; each of the others in turn, at most this often</source>
        <translation>当前显示的设备按实时速率读取；其他设备轮流读取，每台最多按此间隔读取一次</translation>
    </message>
    <message>
        <source>running: %1</source>
        <translation>运行中：%1</translation>
    </message>
    <message>
        <source>%1; restarted %2</source>
        <translation>%1；于 %2 重新启动</translation>
    </message>
</context>
<context>
    <name>stepcom::DevicePage</name>
    <message>
        <source>Device</source>
        <translation>设备</translation>
    </message>
    <message>
        <source>ID %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>ID %1 at %2 baud</source>
        <translation>ID %1，波特率 %2</translation>
    </message>
    <message>
        <source>The controller holds %1</source>
        <translation>控制器中的值：%1</translation>
    </message>
    <message>
        <source>Not read yet</source>
        <translation>尚未读取</translation>
    </message>
    <message>
        <source>Changing the controller to %1…</source>
        <translation>正在将控制器更改为 %1…</translation>
    </message>
    <message>
        <source>The controller answers at %1. Save to flash to keep this after a power cycle.</source>
        <translation>控制器已按 %1 应答。请保存到闪存，使其在断电重启后仍然有效。</translation>
    </message>
    <message>
        <source>The controller does not answer with the new settings (%1). It may be using them anyway. Reconnect with the old settings (%2), or connect with the new ones on the Connection page.</source>
        <translation>控制器未按新设置应答（%1），但它可能已经在使用新设置。请用原设置（%2）重新连接，或在“连接”页面用新设置连接。</translation>
    </message>
    <message>
        <source>Reconnecting with the old settings (%1)…</source>
        <translation>正在用原设置（%1）重新连接…</translation>
    </message>
    <message>
        <source>Connected again with the old settings.</source>
        <translation>已用原设置重新连接。</translation>
    </message>
    <message>
        <source>Reconnecting with the old settings failed: %1.</source>
        <translation>用原设置重新连接失败：%1。</translation>
    </message>
    <message>
        <source>Saving to flash…</source>
        <translation>正在保存到闪存…</translation>
    </message>
    <message>
        <source>Saved to flash: the controller keeps its settings after a power cycle.</source>
        <translation>已保存到闪存：控制器断电重启后仍保留这些设置。</translation>
    </message>
    <message>
        <source>Saving to flash failed; see the messages.</source>
        <translation>保存到闪存失败；请查看消息。</translation>
    </message>
    <message>
        <source>Restoring the factory settings…</source>
        <translation>正在恢复出厂设置…</translation>
    </message>
    <message>
        <source>Factory settings restored; StepCom reads the controller again.</source>
        <translation>已恢复出厂设置；StepCom 正在重新读取控制器。</translation>
    </message>
    <message>
        <source>Restoring the factory settings failed; see the messages.</source>
        <translation>恢复出厂设置失败；请查看消息。</translation>
    </message>
    <message>
        <source>Change device ID and baud rate</source>
        <translation>更改设备 ID 和波特率</translation>
    </message>
    <message>
        <source>Change the controller from %1 to %2?</source>
        <translation>将控制器从 %1 更改为 %2？</translation>
    </message>
    <message>
        <source>&amp;Change</source>
        <translation>更改(&amp;C)</translation>
    </message>
    <message>
        <source>motors 1 to %1</source>
        <translation>电机 1 至电机 %1</translation>
    </message>
    <message>
        <source>the motor</source>
        <translation>电机</translation>
    </message>
    <message>
        <source>every motor parameter of %1: step angle, microsteps, start and accel/decel frequency, direction, speed, pitch, move distance</source>
        <translation>%1的全部参数：步距角、细分、启动频率、加减频率、方向、速度、螺距、单次运行距离</translation>
    </message>
    <message>
        <source>the limit and home inputs</source>
        <translation>限位与原点信号输入口</translation>
    </message>
    <message>
        <source>the homing order</source>
        <translation>回零顺序</translation>
    </message>
    <message>
        <source>the arc and line interpolation setup</source>
        <translation>圆弧插补和直线插补设置</translation>
    </message>
    <message>
        <source>the system mode and its number of round trips</source>
        <translation>系统模式及往返次数</translation>
    </message>
    <message>
        <source>These settings in the controller are replaced by the factory values:</source>
        <translation>控制器中的以下设置将被出厂值替换：</translation>
    </message>
    <message>
        <source>The device ID (%1) and the baud rate (%2) are kept, so StepCom stays connected. Edits not written yet stay in StepCom. The flash keeps the old settings until you save to flash.</source>
        <translation>设备 ID（%1）和波特率（%2）保持不变，因此 StepCom 会保持连接。尚未写入的修改仍保留在 StepCom 中。在保存到闪存之前，闪存中仍是原来的设置。</translation>
    </message>
    <message>
        <source>Restore factory settings</source>
        <translation>恢复出厂设置</translation>
    </message>
    <message>
        <source>Restore the controller&apos;s factory settings?</source>
        <translation>要恢复控制器的出厂设置吗？</translation>
    </message>
    <message>
        <source>&amp;Restore factory settings</source>
        <translation>恢复出厂设置(&amp;R)</translation>
    </message>
    <message>
        <source>Device ID and baud rate</source>
        <translation>设备 ID 和波特率</translation>
    </message>
    <message>
        <source>Flash memory</source>
        <translation>闪存</translation>
    </message>
    <message>
        <source>Factory settings</source>
        <translation>出厂设置</translation>
    </message>
    <message>
        <source>Device &amp;ID:</source>
        <translation>设备 ID(&amp;I)：</translation>
    </message>
    <message>
        <source>&amp;Baud rate:</source>
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <source>The device ID matters on RS-485, where several controllers share the bus. On Modbus TCP only the ID can be changed here.</source>
        <translation>在 RS-485 上，多个控制器共用一条总线，设备 ID 用于区分它们。使用 Modbus TCP 时，这里只能更改设备 ID。</translation>
    </message>
    <message>
        <source>&amp;Apply ID and baud…</source>
        <translation>应用 ID 和波特率(&amp;A)…</translation>
    </message>
    <message>
        <source>Reconnect with the &amp;old settings</source>
        <translation>用原设置重新连接(&amp;O)</translation>
    </message>
    <message>
        <source>Written values take effect at once but live in working memory: without saving to flash, the controller forgets them when it is switched off.</source>
        <translation>写入的值立即生效，但只保存在运行内存中：如果不保存到闪存，控制器断电后这些值将丢失。</translation>
    </message>
    <message>
        <source>Changes not saved to flash.</source>
        <translation>更改尚未保存到闪存。</translation>
    </message>
    <message>
        <source>&amp;Save to flash</source>
        <translation>保存到闪存(&amp;S)</translation>
    </message>
    <message>
        <source>Puts every motor parameter, the limits, the homing order, the interpolation setup and the mode back to the factory values. The device ID and baud rate are kept.</source>
        <translation>将所有电机参数、限位、回零顺序、插补设置和系统模式恢复为出厂值。设备 ID 和波特率保持不变。</translation>
    </message>
    <message>
        <source>Restore &amp;factory settings…</source>
        <translation>恢复出厂设置(&amp;F)…</translation>
    </message>
    <message>
        <source>The controller switches at once. StepCom follows it and checks that it answers; if it does not, you can reconnect with the old settings.

Every other master on the bus must use the new settings too, and no other device may use the new ID. Unsaved, they last until the next power-off.</source>
        <translation>控制器会立即切换。StepCom 随之切换并检查控制器是否应答；如果没有应答，可以用原设置重新连接。

总线上的其他主站也必须改用新设置，并且新 ID 不能与其他设备重复。未保存时，新设置只保持到下次断电。</translation>
    </message>
    <message>
        <source>Save to flash at the new settings (else lost at power-off)</source>
        <translation>在新设置下保存到闪存（否则断电后丢失）</translation>
    </message>
</context>
<context>
    <name>stepcom::DeviceSession</name>
    <message>
        <source>Cannot connect: %1</source>
        <translation>无法连接：%1</translation>
    </message>
    <message>
        <source>Link lost: %1</source>
        <translation>连接中断：%1</translation>
    </message>
    <message>
        <source>Cannot start the built-in simulator: %1</source>
        <translation>无法启动内置仿真器：%1</translation>
    </message>
    <message>
        <source>disconnected by the user</source>
        <translation>用户已断开连接</translation>
    </message>
    <message>
        <source>Reading failed: %1</source>
        <translation>读取失败：%1</translation>
    </message>
    <message numerus="yes">
        <source>Wrote and verified %n parameter(s)</source>
        <translation>
            <numerusform>已写入并验证 %n 个参数</numerusform>
        </translation>
    </message>
    <message>
        <source>Unknown command %1</source>
        <translation>未知命令 %1</translation>
    </message>
    <message>
        <source>%1: done</source>
        <translation>%1：完成</translation>
    </message>
    <message>
        <source>E-STOP: not connected, nothing was sent</source>
        <translation>急停：未连接，未发送任何命令</translation>
    </message>
    <message>
        <source>emergency stop</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>E-STOP sent</source>
        <translation>已发送急停</translation>
    </message>
    <message>
        <source>The controller answers at %1</source>
        <translation>控制器已按 %1 应答</translation>
    </message>
    <message>
        <source>The controller does not answer with the new settings: %1</source>
        <translation>控制器未按新设置应答：%1</translation>
    </message>
    <message>
        <source>switching to %1</source>
        <translation>正在切换到 %1</translation>
    </message>
    <message>
        <source>Read %1 in %2</source>
        <comment>%1: n parameters, %2: n requests</comment>
        <translation>已读取 %1，共 %2</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s)</source>
        <translation>
            <numerusform>%n 个参数</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n request(s)</source>
        <translation>
            <numerusform>%n 次请求</numerusform>
        </translation>
    </message>
    <message>
        <source>the built-in simulator was replaced</source>
        <translation>内置模拟器已被替换</translation>
    </message>
    <message>
        <source>this program has no built-in simulator</source>
        <translation>此程序没有内置模拟器</translation>
    </message>
    <message>
        <source>the page was left</source>
        <translation>离开了此页面</translation>
    </message>
    <message>
        <source>the window lost focus</source>
        <translation>窗口失去焦点</translation>
    </message>
    <message>
        <source>the window closes</source>
        <translation>窗口正在关闭</translation>
    </message>
    <message>
        <source>Opened %1; asking the controller</source>
        <translation>已打开 %1；正在询问控制器</translation>
    </message>
    <message>
        <source>The port is open, but the controller at %1 does not answer.</source>
        <translation>端口已打开，但 %1 处的控制器没有应答。</translation>
    </message>
    <message>
        <source>The controller answers.</source>
        <translation>控制器已应答。</translation>
    </message>
    <message>
        <source>%1: sent</source>
        <translation>%1：已发送</translation>
    </message>
    <message numerus="yes">
        <source>E-STOP sent to %n controller(s): id %1</source>
        <translation>
            <numerusform>急停已发送给 %n 台控制器：ID %1</numerusform>
        </translation>
    </message>
    <message>
        <source>E-STOP acknowledged by every controller: id %1</source>
        <translation>所有控制器都已确认急停：ID %1</translation>
    </message>
    <message>
        <source>E-STOP NOT acknowledged by id %1 (%2); acknowledged by: %3</source>
        <translation>ID %1 未确认急停（%2）；已确认的：%3</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Device id %1 is not on this line (%2)</source>
        <translation>设备 ID %1 不在这条总线上（%2）</translation>
    </message>
    <message>
        <source>showing device %1</source>
        <translation>切换到设备 %1</translation>
    </message>
    <message>
        <source>Device %1: %2</source>
        <translation>设备 %1：%2</translation>
    </message>
    <message>
        <source>The link is back at %1 (attempt %2): reading the status, then everything</source>
        <translation>连接已在 %1 恢复（第 %2 次尝试）：先读取状态，再读取全部参数</translation>
    </message>
    <message>
        <source>Reconnecting cancelled: Connect tries again.</source>
        <translation>已取消重新连接：按“连接”可再次尝试。</translation>
    </message>
    <message>
        <source>E-STOP: the link is down, the controller did NOT get it; it is sent first when the link is back</source>
        <translation>急停：连接已中断，控制器尚未收到急停；连接恢复后将首先发送</translation>
    </message>
    <message>
        <source>Trying to connect again on its own (Cancel stops it).</source>
        <translation>正在自动重新连接（按“取消”停止）。</translation>
    </message>
    <message>
        <source>The controller refuses reads that cover reserved registers; from now on only its listed registers are read (a few more requests).</source>
        <translation>控制器拒绝覆盖保留寄存器的读取；此后只读取已列出的寄存器（请求会略多几次）。</translation>
    </message>
    <message>
        <source>%1 (register %2) is not supported by this controller: it refuses to read it. It is left out from now on.</source>
        <translation>%1（寄存器 %2）此控制器不支持：控制器拒绝读取它。此后不再读取。</translation>
    </message>
    <message>
        <source>Device id %1: %2</source>
        <translation>设备 ID %1：%2</translation>
    </message>
    <message>
        <source>it refuses reads that cover reserved registers, so only its listed registers are read</source>
        <translation>它拒绝覆盖保留寄存器的读取，因此只读取已列出的寄存器</translation>
    </message>
    <message>
        <source>it does not support %1</source>
        <translation>它不支持 %1</translation>
    </message>
    <message>
        <source>Known from an earlier connection to this controller: %1.</source>
        <translation>此前连接该控制器时已知：%1。</translation>
    </message>
    <message>
        <source>A step move still runs on device %1: wait for its end or stop it, then show device %2</source>
        <translation>设备 %1 上的单步移动仍在进行：请等它结束或停止它，然后再显示设备 %2</translation>
    </message>
    <message>
        <source>the port is not open</source>
        <translation>端口未打开</translation>
    </message>
    <message>
        <source>%1 of id %2 is written only while it is the device in view</source>
        <translation>ID %2 的 %1 只能在它是当前显示的设备时写入</translation>
    </message>
    <message>
        <source>%1: done; the controller answered after %2 s</source>
        <translation>%1：完成；控制器在 %2 s 后应答</translation>
    </message>
    <message>
        <source>Device %1: </source>
        <translation>设备 %1：</translation>
    </message>
    <message>
        <source>The controller may have restarted (%1), but reading it again failed: %2</source>
        <translation>控制器可能重新启动了（%1），但重新读取失败：%2</translation>
    </message>
    <message>
        <source>The controller answers again (%1); what it holds is what StepCom held: nothing shows a restart.</source>
        <translation>控制器重新应答了（%1）；它保存的值与 StepCom 所知相同：没有迹象表明重新启动。</translation>
    </message>
    <message>
        <source>positions lost</source>
        <translation>位置丢失</translation>
    </message>
    <message>
        <source>references lost</source>
        <translation>参考点丢失</translation>
    </message>
    <message>
        <source>changes not saved to flash lost: %1</source>
        <translation>未保存到闪存的修改丢失：%1</translation>
    </message>
    <message>
        <source>The controller restarted (power off?): %1. Seen: %2.</source>
        <translation>控制器重新启动了（断电？）：%1。依据：%2。</translation>
    </message>
    <message>
        <source>Factory reset: reading it back failed: %1</source>
        <translation>恢复出厂设置：回读失败：%1</translation>
    </message>
    <message>
        <source>Factory reset: read back, every value is the factory value.</source>
        <translation>恢复出厂设置：已回读，每个值都是出厂值。</translation>
    </message>
    <message numerus="yes">
        <source>Factory reset: read back; %n value(s) differ from the factory values StepCom knows (another firmware&apos;s defaults?): %1</source>
        <translation>
            <numerusform>恢复出厂设置：已回读；有 %n 个值与 StepCom 所知的出厂值不同（其他固件的默认值？）：%1</numerusform>
        </translation>
    </message>
    <message>
        <source>The controller restarted (power off?): positions lost; references lost. Seen: %1. Reading it again failed (%2): what else it lost is not known.</source>
        <translation>控制器重新启动了（断电？）：位置丢失；参考点丢失。所见：%1。重新读取失败（%2）：不知道还丢失了什么。</translation>
    </message>
    <message>
        <source>The controller may have restarted (power off?): %1. Every axis reads 0, but only axes that were moving went there: whether they ended there or the controller restarted cannot be told. The references are not known: home again.</source>
        <translation>控制器可能重新启动了（断电？）：%1。所有轴都读到 0，但变成 0 的只有原在运动的轴：无法判断是运动恰好停在那里，还是控制器重新启动了。参考点未知：请重新回零。</translation>
    </message>
</context>
<context>
    <name>stepcom::DirectionCheck</name>
    <message>
        <source>motor %1 has no direction register in this register map</source>
        <translation>此寄存器表中电机 %1 没有方向寄存器</translation>
    </message>
    <message>
        <source>%1 does not have exactly two values: StepCom cannot flip it</source>
        <translation>%1 不是恰好两个取值：StepCom 无法翻转它</translation>
    </message>
</context>
<context>
    <name>stepcom::EmergencyStop</name>
    <message>
        <source>E-STOP</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>Emergency stop: all motors and outputs off (coil 00042). Key: %1</source>
        <translation>急停：停止所有电机并关闭所有输出（线圈 00042）。快捷键：%1</translation>
    </message>
    <message>
        <source>Nothing to stop: a session log is replayed and no controller is connected. Connect to a controller to use the emergency stop.</source>
        <translation>无可停止的对象：正在回放会话日志，未连接控制器。连接控制器后才能使用急停。</translation>
    </message>
    <message>
        <source>Nothing to stop: a profile file is edited and no controller is connected. Connect to a controller to use the emergency stop.</source>
        <translation>无可停止的对象：正在编辑参数文件，未连接控制器。连接控制器后才能使用急停。</translation>
    </message>
</context>
<context>
    <name>stepcom::EstopConfirmation</name>
    <message>
        <source>E-STOP acknowledged by controller %1 (its answer heard; the register map names no motion state to read back)</source>
        <translation>控制器 %1 已确认急停（已听到其应答；寄存器映射中没有可回读的运动状态）</translation>
    </message>
    <message>
        <source>E-STOP acknowledged by controller %1: both axes stopped</source>
        <translation>控制器 %1 已确认急停：两轴均已停止</translation>
    </message>
    <message numerus="yes">
        <source>E-STOP acknowledged by controller %1: %n axis(es) stopped</source>
        <translation>
            <numerusform>控制器 %1 已确认急停：%n 个轴已停止</numerusform>
        </translation>
    </message>
    <message>
        <source>Stop the machine by its own E-STOP.</source>
        <translation>请用机器自身的急停停机。</translation>
    </message>
    <message>
        <source>E-STOP not acknowledged by controller %1: motor %2 still running after %3 E-STOPs. %4</source>
        <translation>控制器 %1 未确认急停：发送 %3 次急停后电机 %2 仍在运行。%4</translation>
    </message>
    <message>
        <source>E-STOP not acknowledged by controller %1: a copy of it was heard, but the controller never answered the read of its motion state. %2</source>
        <translation>控制器 %1 未确认急停：听到了它的副本，但控制器始终没有应答对其运动状态的读取。%2</translation>
    </message>
    <message>
        <source>E-STOP not acknowledged by controller %1: only our own echo heard (sent %2 times). %3</source>
        <translation>控制器 %1 未确认急停：只听到了自己的回显（已发送 %2 次）。%3</translation>
    </message>
    <message>
        <source>E-STOP sent %1 times into the other master&apos;s line, and controller %2 never answered it. %3</source>
        <translation>急停已向另一个主站的线路发送 %1 次，控制器 %2 始终没有应答。%3</translation>
    </message>
</context>
<context>
    <name>stepcom::FaultInjector</name>
    <message>
        <source>&apos;%1&apos; is not a share between 0 and 1 (or 0%-100%)</source>
        <translation>“%1”不是 0 到 1 之间的比例（或 0%-100%）</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: expected SHARE:NUMBER, e.g. 0.1:500</source>
        <translation>“%1”：应为 比例:数值 格式，例如 0.1:500</translation>
    </message>
</context>
<context>
    <name>stepcom::GamepadJog</name>
    <message>
        <source>the pad went silent</source>
        <translation>手柄没有了信号</translation>
    </message>
    <message>
        <source>the pad was switched off</source>
        <translation>手柄已关闭</translation>
    </message>
    <message>
        <source>E-STOP on the pad</source>
        <translation>手柄上的急停</translation>
    </message>
    <message>
        <source>stop on the pad</source>
        <translation>手柄上的停止</translation>
    </message>
    <message>
        <source>the dead-man was let go</source>
        <translation>松开了使能键</translation>
    </message>
    <message>
        <source>the stick was let go</source>
        <translation>松开了摇杆</translation>
    </message>
    <message>
        <source>the pad was unplugged</source>
        <translation>手柄已拔出</translation>
    </message>
    <message>
        <source>Pad: %1, the jog stopped</source>
        <translation>手柄：%1，点动已停止</translation>
    </message>
</context>
<context>
    <name>stepcom::GamepadMapping</name>
    <message>
        <source>unknown key &quot;%1&quot; in the pad&apos;s mapping</source>
        <translation>手柄映射中有未知的键“%1”</translation>
    </message>
    <message>
        <source>&quot;%1&quot; names no button of a pad</source>
        <translation>“%1”不是手柄上的按键</translation>
    </message>
    <message>
        <source>the dead zone must be a number from 0.05 to 0.9</source>
        <translation>死区必须是 0.05 到 0.9 之间的数</translation>
    </message>
    <message>
        <source>&quot;invert_y&quot; must be true or false</source>
        <translation>“invert_y”必须是 true 或 false</translation>
    </message>
    <message>
        <source>one button cannot do two things in the pad&apos;s mapping</source>
        <translation>手柄映射中一个按键不能有两个功能</translation>
    </message>
    <message>
        <source>left trigger</source>
        <translation>左扳机</translation>
    </message>
    <message>
        <source>right trigger</source>
        <translation>右扳机</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Back 键</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start 键</translation>
    </message>
    <message>
        <source>left shoulder</source>
        <translation>左肩键</translation>
    </message>
    <message>
        <source>right shoulder</source>
        <translation>右肩键</translation>
    </message>
    <message>
        <source>button %1</source>
        <translation>按键 %1</translation>
    </message>
</context>
<context>
    <name>stepcom::GamepadPanel</name>
    <message>
        <source>Not changed: %1.</source>
        <translation>未修改：%1。</translation>
    </message>
    <message>
        <source>Game pads cannot be read: %1</source>
        <translation>无法读取手柄：%1</translation>
    </message>
    <message>
        <source>Off: tick it to jog with a game pad.</source>
        <translation>已关闭：勾选后可用手柄点动。</translation>
    </message>
    <message>
        <source>No pad connected: plug one in or pair it (Bluetooth).</source>
        <translation>未连接手柄：请插入或配对（蓝牙）。</translation>
    </message>
    <message>
        <source>, wired</source>
        <translation>，有线</translation>
    </message>
    <message>
        <source>, battery about %1 %</source>
        <translation>，电量约 %1 %</translation>
    </message>
    <message>
        <source>Connected: %1%2</source>
        <translation>已连接：%1%2</translation>
    </message>
    <message>
        <source>Hold %1 (the dead-man) and move the left stick or the D-pad to jog; %2 stops, %3 is the E-STOP.</source>
        <translation>按住 %1（使能键）并拨动左摇杆或方向键即可点动；%2 停止，%3 为急停。</translation>
    </message>
    <message>
        <source>motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>Jogging %1 from the pad.</source>
        <translation>正在用手柄点动 %1。</translation>
    </message>
    <message>
        <source>Home the machine in its homing order? The axes will move to their home switches.</source>
        <translation>按回零顺序让机器回原点吗？各轴将移动到原点开关。</translation>
    </message>
    <message>
        <source>Home from the pad</source>
        <translation>从手柄回原点</translation>
    </message>
    <message>
        <source>Game pad</source>
        <translation>手柄</translation>
    </message>
    <message>
        <source>&amp;Jog with a game pad</source>
        <translation>用手柄点动(&amp;J)</translation>
    </message>
    <message>
        <source>The pad jogs only while its dead-man is held; unplugged or silent, it stops what it jogs.</source>
        <translation>只有按住使能键时手柄才会点动；拔出或没有信号时，它所点动的轴会停止。</translation>
    </message>
    <message>
        <source>Dead-man (hold):</source>
        <translation>使能键（按住）：</translation>
    </message>
    <message>
        <source>Stop:</source>
        <translation>停止：</translation>
    </message>
    <message>
        <source>Home:</source>
        <translation>回原点：</translation>
    </message>
    <message>
        <source>E-STOP:</source>
        <translation>急停：</translation>
    </message>
    <message>
        <source>Dead zone:</source>
        <translation>死区：</translation>
    </message>
</context>
<context>
    <name>stepcom::GuideWindow</name>
    <message>
        <source>The user guide (%1) was not found in %2. It is installed with StepCom; reinstalling the package brings it back.</source>
        <translation>在 %2 中找不到使用手册（%1）。手册随 StepCom 一起安装；重新安装软件包即可恢复。</translation>
    </message>
    <message>
        <source>The guide has no section &quot;%1&quot;.</source>
        <translation>手册中没有“%1”这一章节。</translation>
    </message>
    <message>
        <source>%1 is not installed with the guide.</source>
        <translation>%1 没有随手册一起安装。</translation>
    </message>
    <message>
        <source>User guide</source>
        <translation>使用手册</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>返回</translation>
    </message>
    <message>
        <source>Back to where you were in the guide</source>
        <translation>回到手册中刚才的位置</translation>
    </message>
    <message>
        <source>Go to a section of the guide</source>
        <translation>跳到手册的某一章节</translation>
    </message>
    <message>
        <source>Sections</source>
        <translation>章节</translation>
    </message>
</context>
<context>
    <name>stepcom::HeardEvent</name>
    <message>
        <source> (answered in %1 ms)</source>
        <translation>（%1 ms 内应答）</translation>
    </message>
    <message>
        <source>coils %1-%2</source>
        <translation>线圈 %1-%2</translation>
    </message>
    <message>
        <source>coil %1</source>
        <translation>线圈 %1</translation>
    </message>
    <message>
        <source>PLC read %1 from id %2: %3%4</source>
        <translation>PLC 从站号 %2 读取 %1：%3%4</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s)</source>
        <translation>
            <numerusform>%n 个值</numerusform>
        </translation>
    </message>
    <message>
        <source>PLC wrote %1 to id %2%3</source>
        <translation>PLC 向站号 %2 写入 %1%3</translation>
    </message>
    <message>
        <source>PLC sent %1 to id %2%3</source>
        <translation>PLC 向站号 %2 发送 %1%3</translation>
    </message>
    <message>
        <source>id %1 refused the PLC&apos;s FC%2 at %3: %4</source>
        <translation>站号 %1 拒绝了 PLC 在 %3 的 FC%2：%4</translation>
    </message>
    <message>
        <source>id %1 did not answer the PLC&apos;s FC%2 at %3%4</source>
        <translation>站号 %1 未应答 PLC 在 %3 的 FC%2%4</translation>
    </message>
    <message>
        <source>PLC broadcast FC%1 at %2 to every id: %3</source>
        <translation>PLC 向所有站号广播 %2 的 FC%1：%3</translation>
    </message>
    <message>
        <source>an answer from id %1 (FC%2) whose request was not heard</source>
        <translation>来自站号 %1 的应答（FC%2），未听到其请求</translation>
    </message>
</context>
<context>
    <name>stepcom::HomingOrderEditor</name>
    <message>
        <source>%1 is already the %2 in the homing order: a motor homes once. Set the %2 to %3 first.</source>
        <translation>%1 已是回零顺序中的%2：每个电机只回零一次。请先将%2设为“%3”。</translation>
    </message>
    <message>
        <source>no motor</source>
        <translation>无</translation>
    </message>
    <message>
        <source>%1, then %2</source>
        <translation>先%1，后%2</translation>
    </message>
    <message>
        <source>1st</source>
        <translation>第 1 个</translation>
    </message>
    <message>
        <source>2nd</source>
        <translation>第 2 个</translation>
    </message>
    <message>
        <source>1st to home:</source>
        <translation>第 1 个回零：</translation>
    </message>
    <message>
        <source>2nd to home:</source>
        <translation>第 2 个回零：</translation>
    </message>
    <message>
        <source>Not read from the controller yet</source>
        <translation>尚未从控制器读取</translation>
    </message>
    <message>
        <source>The controller holds this order</source>
        <translation>与控制器中的回零顺序一致</translation>
    </message>
    <message>
        <source>Edited, not written yet: apply the order</source>
        <translation>已修改，尚未写入：请应用回零顺序</translation>
    </message>
    <message>
        <source>Write failed: %1</source>
        <translation>写入失败：%1</translation>
    </message>
    <message>
        <source>Not supported by this controller</source>
        <translation>此控制器不支持</translation>
    </message>
</context>
<context>
    <name>stepcom::IdAssigner</name>
    <message>
        <source>Connect to the line first (the port the controllers are on, %1 baud, device id %2), then start the assistant.</source>
        <translation>请先连接总线（控制器所在的端口，%1 波特率，设备 ID %2），再启动向导。</translation>
    </message>
    <message>
        <source>Connect the first controller, alone (a new one answers at id %1, %2 baud), then press Next. It gets id %3.</source>
        <translation>只接上第一台控制器（新控制器在 ID %1、%2 波特率下应答），然后按“下一步”。它将得到 ID %3。</translation>
    </message>
    <message>
        <source>No free id is left (every id from %1 to 255 is on the list).</source>
        <translation>没有空闲的 ID 了（从 %1 到 255 的每个 ID 都在列表中）。</translation>
    </message>
    <message>
        <source>Giving the controller at id %1 the id %2…</source>
        <translation>正在把 ID %1 上的控制器改为 ID %2…</translation>
    </message>
    <message>
        <source>Cannot open the port at %1 baud: %2</source>
        <translation>无法以 %1 波特率打开端口：%2</translation>
    </message>
    <message>
        <source>Refused: %1. Two controllers with the same id answer at once and garble each other&apos;s answers; nothing was written.</source>
        <translation>拒绝：%1。两台相同 ID 的控制器同时应答，互相干扰成乱码；未写入任何内容。</translation>
    </message>
    <message>
        <source>The controller did not get id %1: %2. Check it is the only new controller on the line, then press Next to try again.</source>
        <translation>控制器没有得到 ID %1：%2。请确认它是总线上唯一的新控制器，然后按“下一步”重试。</translation>
    </message>
    <message>
        <source>%1. Connect the next controller, alone, then press Next (it gets id %2), or Finish.</source>
        <translation>%1。只接上下一台控制器，然后按“下一步”（它将得到 ID %2），或按“完成”。</translation>
    </message>
    <message>
        <source>Moving the line to %1 baud…</source>
        <translation>正在把总线切换到 %1 波特率…</translation>
    </message>
    <message>
        <source>Asking id %1 at %2 baud</source>
        <translation>正在以 %2 波特率询问 ID %1</translation>
    </message>
    <message>
        <source>Finished: no controller was given an id.</source>
        <translation>已完成：没有控制器被分配 ID。</translation>
    </message>
    <message>
        <source>Finished: the line is at %1 baud; every controller given an id answers: id %2.</source>
        <translation>已完成：总线为 %1 波特率；每台已分配 ID 的控制器都在应答：ID %2。</translation>
    </message>
    <message>
        <source>Finished: the line is at %1 baud. Answering: id %2. NOT answering: id %3 — check its power and wiring; it stays on the device list.</source>
        <translation>已完成：总线为 %1 波特率。应答中：ID %2。无应答：ID %3——请检查其电源和接线；它仍保留在设备列表中。</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
</context>
<context>
    <name>stepcom::IdAssistantDialog</name>
    <message>
        <source>Wait: a controller is being changed. The window closes when it is done.</source>
        <translation>请稍候：正在修改一台控制器。完成后窗口自动关闭。</translation>
    </message>
    <message>
        <source>Assign device ids</source>
        <translation>分配设备 ID</translation>
    </message>
    <message>
        <source>Gives each controller of a new line its own id. Every controller leaves the factory with id %1 at %2 baud, so connect them one at a time: connect one, press Next, wait until it answers at its new id, then connect the next. A new id or baud takes effect at once; the assistant follows each controller and checks that it answers at its new id and no longer at id %1.</source>
        <translation>为新总线上的每台控制器分配各自的 ID。每台控制器出厂时都是 ID %1、%2 波特率，所以请逐台连接：接上一台，按“下一步”，等它在新 ID 上应答后再接下一台。新的 ID 或波特率立即生效；向导会跟随每台控制器，并确认它在新 ID 上应答、在 ID %1 上不再应答。</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>设置</translation>
    </message>
    <message>
        <source>First id to give:</source>
        <translation>要分配的第一个 ID：</translation>
    </message>
    <message>
        <source>Common baud rate:</source>
        <translation>统一波特率：</translation>
    </message>
    <message>
        <source>Name of the next controller:</source>
        <translation>下一台控制器的名称：</translation>
    </message>
    <message>
        <source>keep %1 (factory)</source>
        <translation>保持 %1（出厂值）</translation>
    </message>
    <message>
        <source>New line: start with an empty device list</source>
        <translation>新总线：从空的设备列表开始</translation>
    </message>
    <message>
        <source>optional, e.g. X/Y table</source>
        <translation>可选，例如 X/Y 工作台</translation>
    </message>
    <message>
        <source>Id</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <source>Next: the controller is connected</source>
        <translation>下一步：控制器已接好</translation>
    </message>
    <message>
        <source>Finish</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Press Start. The line&apos;s port is open at %1.</source>
        <translation>请按“开始”。总线端口已打开：%1。</translation>
    </message>
    <message>
        <source>Connect to the line first (the port the controllers are on, %1 baud, device id %2), then press Start.</source>
        <translation>请先连接总线（控制器所在的端口，%1 波特率，设备 ID %2），再按“开始”。</translation>
    </message>
    <message>
        <source>Save each id to flash (else lost at power-off)</source>
        <translation>把每个 ID 保存到闪存（否则断电后丢失）</translation>
    </message>
    <message>
        <source>Without saving, a controller is back at id %1 and %2 baud after its next power-off.</source>
        <translation>不保存时，控制器下次断电后会回到 ID %1、%2 波特。</translation>
    </message>
</context>
<context>
    <name>stepcom::IdChange</name>
    <message>
        <source>device ids are 1 to 255 (asked: %1 → %2)</source>
        <translation>设备 ID 为 1 到 255（要求的是：%1 → %2）</translation>
    </message>
    <message>
        <source>the controller already has id %1</source>
        <translation>控制器已经是 ID %1</translation>
    </message>
    <message>
        <source>the register map has no device.id</source>
        <translation>寄存器表中没有 device.id</translation>
    </message>
    <message>
        <source>the register map has no device.baud</source>
        <translation>寄存器表中没有 device.baud</translation>
    </message>
    <message>
        <source>not connected: connect to the line first</source>
        <translation>未连接：请先连接总线</translation>
    </message>
    <message>
        <source>Asking the controller at id %1</source>
        <translation>正在询问 ID %1 上的控制器</translation>
    </message>
    <message>
        <source>garbled answers at id %1: two or more controllers answer there. Connect only the controller that is to get id %2, then try again</source>
        <translation>ID %1 上应答乱码：有两台以上控制器在此应答。请只接上要得到 ID %2 的那台控制器，然后重试</translation>
    </message>
    <message>
        <source>no controller answers at id %1: %2</source>
        <translation>ID %1 上没有控制器应答：%2</translation>
    </message>
    <message>
        <source>Making sure nobody answers at id %1 yet</source>
        <translation>正在确认 ID %1 上还没有控制器应答</translation>
    </message>
    <message>
        <source>id %1 is taken: a controller answers there already. Choose a free id</source>
        <translation>ID %1 已被占用：已有控制器在此应答。请选择一个空闲的 ID</translation>
    </message>
    <message>
        <source>Writing id %1 to the controller at id %2</source>
        <translation>正在把 ID %1 写入 ID %2 上的控制器</translation>
    </message>
    <message>
        <source>the controller does not answer at id %1: %2</source>
        <translation>控制器在 ID %1 上没有应答：%2</translation>
    </message>
    <message>
        <source>Making sure nobody answers at id %1 any more</source>
        <translation>正在确认 ID %1 上已无应答</translation>
    </message>
    <message>
        <source>the controller answers at id %1 now, but a controller still answers at id %2: more than one controller was connected. Disconnect all but one and try again</source>
        <translation>控制器现在在 ID %1 上应答，但 ID %2 上仍有控制器应答：接上了不止一台控制器。请只保留一台，然后重试</translation>
    </message>
    <message>
        <source>Writing baud %1 to the controller at id %2</source>
        <translation>正在把波特率 %1 写入 ID %2 上的控制器</translation>
    </message>
    <message>
        <source>the controller has id %1, but does not answer at %2 baud: %3</source>
        <translation>控制器已是 ID %1，但在 %2 波特率下没有应答：%3</translation>
    </message>
    <message>
        <source>device id %1 → %2: the controller answers at id %2 at %3 baud</source>
        <translation>设备 ID %1 → %2：控制器在 ID %2、%3 波特率下应答</translation>
    </message>
    <message>
        <source>device id %1 → %2: the controller answers at id %2</source>
        <translation>设备 ID %1 → %2：控制器在 ID %2 上应答</translation>
    </message>
    <message>
        <source>the controller answers at id %1, but the register map has no save_to_flash: the id lasts until the power is switched off</source>
        <translation>控制器在 ID %1 应答，但寄存器表中没有 save_to_flash：该 ID 只保持到断电为止</translation>
    </message>
    <message>
        <source>Saving to flash at id %1</source>
        <translation>正在 ID %1 保存到闪存</translation>
    </message>
    <message>
        <source>the controller answers at id %1, but saving to flash failed (%2): the id lasts until the power is switched off; save to flash again</source>
        <translation>控制器在 ID %1 应答，但保存到闪存失败（%2）：该 ID 只保持到断电为止；请再次保存到闪存</translation>
    </message>
    <message>
        <source>; saved to flash</source>
        <translation>；已保存到闪存</translation>
    </message>
    <message>
        <source>; not saved to flash: lost at power-off</source>
        <translation>；未保存到闪存：断电后丢失</translation>
    </message>
</context>
<context>
    <name>stepcom::IdList</name>
    <message>
        <source>&apos;%1&apos; is not a device id or a range of ids (e.g. 1,2,3 or 1-3)</source>
        <translation>“%1”不是设备 ID，也不是 ID 范围（例如 1,2,3 或 1-3）</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: device ids are 1-255</source>
        <translation>“%1”：设备 ID 为 1-255</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: the range runs backwards</source>
        <translation>“%1”：范围的起点大于终点</translation>
    </message>
    <message>
        <source>device id %1 is given twice</source>
        <translation>设备 ID %1 给了两次</translation>
    </message>
</context>
<context>
    <name>stepcom::InputTest</name>
    <message>
        <source>positive limit</source>
        <translation>正限位</translation>
    </message>
    <message>
        <source>negative limit</source>
        <translation>反限位</translation>
    </message>
    <message>
        <source>home switch</source>
        <translation>原点开关</translation>
    </message>
    <message>
        <source>the %1 of motor %2</source>
        <translation>电机 %2 的%1</translation>
    </message>
    <message>
        <source>No input changed while %1 was pressed, and none is configured for it. If the machine has no such switch, skip this step; otherwise check the switch, its wiring and its 24 V supply.</source>
        <translation>按下%1时没有输入发生变化，也没有为它配置输入。如果机器没有这个开关，请跳过此步骤；否则请检查开关、接线和 24 V 电源。</translation>
    </message>
    <message>
        <source>No input changed while %1 was pressed (configured: %2). Check the switch, its wiring and its 24 V supply (the inputs are active on a 24 V negative signal), then try again.</source>
        <translation>按下%1时没有输入发生变化（配置为：%2）。请检查开关、接线和 24 V 电源（输入口在 24 V 负极信号时有效），然后重试。</translation>
    </message>
    <message>
        <source>Several inputs changed while %1 was pressed (%2): press only this switch and try again.</source>
        <translation>按下%1时有多个输入发生变化（%2）：请只按这一个开关，然后重试。</translation>
    </message>
    <message>
        <source>%1 is also configured as the %2 of motor %3</source>
        <translation>%1 同时被配置为电机 %3 的%2</translation>
    </message>
    <message>
        <source>%1 answered for %2, as configured.</source>
        <translation>%2响应在 %1，与配置一致。</translation>
    </message>
    <message>
        <source>%1 answered for %2, which is not configured (none). Proposed: %3.</source>
        <translation>%2响应在 %1，但它未配置（无）。建议：%3。</translation>
    </message>
    <message>
        <source>%1 answered for %2, but %3 is configured: the wiring and the configuration disagree. Proposed: %4 (or rewire the switch to %3).</source>
        <translation>%2响应在 %1，但配置的是 %3：接线与配置不一致。建议：%4（或将开关改接到 %3）。</translation>
    </message>
    <message>
        <source>%1 answered for %2, and this register map cannot name %1 there.</source>
        <translation>%2响应在 %1，但此寄存器表无法在该处设定 %1。</translation>
    </message>
</context>
<context>
    <name>stepcom::InputsPage</name>
    <message>
        <source>Inputs and limits</source>
        <translation>输入与限位</translation>
    </message>
    <message>
        <source>System mode: not known yet.</source>
        <translation>系统模式：尚未读取。</translation>
    </message>
    <message>
        <source>System mode: %1. The limit and home settings apply.</source>
        <translation>系统模式：%1。限位与原点设置有效。</translation>
    </message>
    <message>
        <source>System mode: %1. Motor 1 uses IN1 and IN2 as its limits, IN3 stops it and IN4 starts it.</source>
        <translation>系统模式：%1。电机 1 以 IN1、IN2 为正、反限位，IN3 急停，IN4 启动。</translation>
    </message>
    <message>
        <source>System mode: %1. The limit settings are ignored: the inputs do what the mode says.</source>
        <translation>系统模式：%1。限位设置无效：各输入口按该模式的规定动作。</translation>
    </message>
    <message>
        <source>motor %1 positive limit</source>
        <translation>电机 %1 正限位</translation>
    </message>
    <message>
        <source>motor %1 negative limit</source>
        <translation>电机 %1 反限位</translation>
    </message>
    <message>
        <source>motor %1 home</source>
        <translation>电机 %1 原点信号</translation>
    </message>
    <message>
        <source>not used as a limit or home</source>
        <translation>未用作限位或原点</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>on</source>
        <translation>开 (ON)</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关 (OFF)</translation>
    </message>
    <message>
        <source>Limit and home inputs</source>
        <translation>限位与原点信号输入</translation>
    </message>
    <message>
        <source>Wiring check</source>
        <translation>接线检查</translation>
    </message>
    <message>
        <source>Inputs (live)</source>
        <translation>输入（实时）</translation>
    </message>
    <message>
        <source>Outputs (live)</source>
        <translation>输出（实时）</translation>
    </message>
    <message>
        <source>Positive limit</source>
        <translation>正限位</translation>
    </message>
    <message>
        <source>Negative limit</source>
        <translation>反限位</translation>
    </message>
    <message>
        <source>Home input</source>
        <translation>原点信号</translation>
    </message>
    <message>
        <source>Motor &amp;%1:</source>
        <translation>电机 &amp;%1：</translation>
    </message>
    <message>
        <source>Homing runs in reverse until the home input is on, so the home input is usually the negative limit&apos;s input. Inputs are on with a 24 V negative (NPN) signal.</source>
        <translation>回机械零时电机一直反转，直到原点信号有效，因此一般情况下原点与反限位设定为同一个输入口。输入端接入 24V 负极（NPN）信号时输入有效。</translation>
    </message>
    <message>
        <source>Output %1</source>
        <translation>输出 %1</translation>
    </message>
</context>
<context>
    <name>stepcom::InterpolationGeometry</name>
    <message>
        <source>Start and end are the same point: three points cannot describe a full circle. Use the centre mode for a full circle.</source>
        <translation>起点与终点相同：三点无法描述整圆。整圆请使用圆心模式。</translation>
    </message>
    <message>
        <source>The middle point %1 is the same as the start or the end point: three distinct points are needed.</source>
        <translation>中间点 %1 与起点或终点相同：需要三个不同的点。</translation>
    </message>
    <message>
        <source>Start, middle and end are on one straight line: no circle passes through them. Use the line editor for a straight move.</source>
        <translation>起点、中间点和终点在同一直线上：没有圆经过这三点。直线运动请使用直线编辑器。</translation>
    </message>
    <message>
        <source>The start point is the centre: the radius is zero.</source>
        <translation>起点即圆心：半径为零。</translation>
    </message>
    <message>
        <source>The end point is the centre: the radius is zero.</source>
        <translation>终点即圆心：半径为零。</translation>
    </message>
    <message>
        <source>Start and end are not the same distance from the centre: start radius %1, end radius %2, difference %3 (at most %4 allowed).</source>
        <translation>起点和终点到圆心的距离不相等：起点半径 %1，终点半径 %2，差值 %3（最大允许 %4）。</translation>
    </message>
    <message>
        <source>Start and end are the same point: this is a full circle.</source>
        <translation>起点与终点相同：这是一个整圆。</translation>
    </message>
    <message>
        <source>The arc in the chosen direction does not pass through the middle point: the controller goes the other way round the circle. Change the direction to pass through it.</source>
        <translation>按所选方向运行的圆弧不经过中间点：控制器会沿圆的另一侧运行。请更改方向以经过中间点。</translation>
    </message>
    <message>
        <source>Start and end are the same point %1: the line has no length.</source>
        <translation>起点与终点是同一点 %1：直线长度为零。</translation>
    </message>
</context>
<context>
    <name>stepcom::InterpolationPage</name>
    <message>
        <source>Interpolation</source>
        <translation>插补</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>圆弧</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>直线</translation>
    </message>
    <message>
        <source>Motor 1 (X) [%1]</source>
        <translation>电机 1 (X) [%1]</translation>
    </message>
    <message>
        <source>Motor 2 (Y) [%1]</source>
        <translation>电机 2 (Y) [%1]</translation>
    </message>
</context>
<context>
    <name>stepcom::InterpolationPreview</name>
    <message>
        <source>&amp;Fit</source>
        <translation>全部显示(&amp;F)</translation>
    </message>
    <message>
        <source>Show the whole path again (or double-click the plot)</source>
        <translation>重新显示整个路径（或双击图表）</translation>
    </message>
    <message>
        <source>Export P&amp;NG…</source>
        <translation>导出 PNG(&amp;N)…</translation>
    </message>
    <message>
        <source>Save the preview as it is shown as a PNG picture</source>
        <translation>将当前显示的预览保存为 PNG 图片</translation>
    </message>
    <message>
        <source>Real run</source>
        <translation>实际运行</translation>
    </message>
    <message>
        <source>Drag to zoom into a region, wheel or +/- to zoom, middle button or arrow keys to pan, double-click to fit.</source>
        <translation>拖动可放大某个区域，滚轮或 +/- 缩放，中键或方向键平移，双击全部显示。</translation>
    </message>
    <message>
        <source>Approach</source>
        <translation>趋近移动</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>圆弧</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>直线</translation>
    </message>
    <message>
        <source>Invalid</source>
        <translation>无效</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>起点</translation>
    </message>
    <message>
        <source>End</source>
        <translation>终点</translation>
    </message>
    <message>
        <source>Middle point</source>
        <translation>中间点</translation>
    </message>
    <message>
        <source>Centre (computed)</source>
        <translation>圆心（计算值）</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>圆心</translation>
    </message>
    <message>
        <source>Invalid: %1</source>
        <translation>无效：%1</translation>
    </message>
    <message>
        <source>Dashed: the approach from the current position; both axes start together, each at its own speed, so the last one finishes alone.</source>
        <translation>虚线：从当前位置到起点的趋近移动；两轴同时启动，各自以自身速度运行，因此较晚到达的一轴最后单独运行。</translation>
    </message>
    <message>
        <source>Dashed: the approach from the current position (the motors&apos; parameters are not known yet: drawn as equal speeds).</source>
        <translation>虚线：从当前位置到起点的趋近移动（电机参数尚未读取：按相同速度绘制）。</translation>
    </message>
    <message>
        <source>path, arrowheads: direction</source>
        <translation>路径，箭头：方向</translation>
    </message>
    <message>
        <source>approach</source>
        <translation>趋近移动</translation>
    </message>
    <message>
        <source>real run</source>
        <translation>实际运行</translation>
    </message>
    <message>
        <source>start</source>
        <translation>起点</translation>
    </message>
    <message>
        <source>end</source>
        <translation>终点</translation>
    </message>
    <message>
        <source>middle point</source>
        <translation>中间点</translation>
    </message>
    <message>
        <source>centre</source>
        <translation>圆心</translation>
    </message>
    <message>
        <source>Export the preview as PNG</source>
        <translation>将预览导出为 PNG</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG 图片 (*.png)</translation>
    </message>
    <message>
        <source>Saved “%1”.</source>
        <translation>已保存“%1”。</translation>
    </message>
</context>
<context>
    <name>stepcom::JogController</name>
    <message>
        <source>Motor %1 has stopped now</source>
        <translation>电机 %1 现已停止</translation>
    </message>
    <message>
        <source>Keyboard jogging is on</source>
        <translation>键盘点动已开启</translation>
    </message>
    <message>
        <source>Keyboard jogging is off</source>
        <translation>键盘点动已关闭</translation>
    </message>
    <message>
        <source>forward</source>
        <translation>正向</translation>
    </message>
    <message>
        <source>reverse</source>
        <translation>反向</translation>
    </message>
    <message>
        <source>There is no motor %1</source>
        <translation>没有电机 %1</translation>
    </message>
    <message>
        <source>Keyboard jogging is off: motor %1 does not move</source>
        <translation>键盘点动已关闭：电机 %1 不运行</translation>
    </message>
    <message>
        <source>Not connected: motor %1 does not move</source>
        <translation>未连接：电机 %1 不运行</translation>
    </message>
    <message>
        <source>Motor %1 already jogs %2: let go of it first</source>
        <translation>电机 %1 已在%2点动：请先松开</translation>
    </message>
    <message>
        <source>Motor %1: the last jog command is still on its way; press again</source>
        <translation>电机 %1：上一条点动命令仍在发送中；请重新按下</translation>
    </message>
    <message>
        <source>Motor %1 may still be running after its stop: stop it before jogging</source>
        <translation>电机 %1 在停止后可能仍在运行：请先使其停止再点动</translation>
    </message>
    <message>
        <source>Motor %1 is moving (a single move, homing or another command): stop it before jogging</source>
        <translation>电机 %1 正在运行（单次运行、回机械零或其他命令）：请先使其停止再点动</translation>
    </message>
    <message>
        <source>Motor %1 has no %2 command in this map</source>
        <translation>寄存器映射中没有电机 %1 的 %2 命令</translation>
    </message>
    <message>
        <source>Motor %1: jog %2</source>
        <translation>电机 %1：%2点动</translation>
    </message>
    <message>
        <source>released</source>
        <translation>已松开</translation>
    </message>
    <message>
        <source>stop button</source>
        <translation>停止按钮</translation>
    </message>
    <message>
        <source>Motor %1 has no stop command in this map: use the emergency stop</source>
        <translation>寄存器映射中没有电机 %1 的停止命令：请使用急停</translation>
    </message>
    <message>
        <source>not connected, the stop could not be sent</source>
        <translation>未连接，无法发送停止命令</translation>
    </message>
    <message>
        <source>Not connected: the stop for motor %1 was not sent</source>
        <translation>未连接：电机 %1 的停止命令未发送</translation>
    </message>
    <message>
        <source>Motor %1: jog %2 failed: %3</source>
        <translation>电机 %1：%2点动失败：%3</translation>
    </message>
    <message>
        <source>the jog command failed</source>
        <translation>点动命令失败</translation>
    </message>
    <message>
        <source>Motor %1: the stop failed: %2</source>
        <translation>电机 %1：停止失败：%2</translation>
    </message>
    <message>
        <source>Motor %1 stopped (%2)</source>
        <translation>电机 %1 已停止（%2）</translation>
    </message>
    <message>
        <source>Motor %1 still runs after its stop (%2)! Use the emergency stop, then check the controller.</source>
        <translation>电机 %1 在停止后仍在运行（%2）！请使用急停，然后检查控制器。</translation>
    </message>
    <message>
        <source>Motor %1: could not check that it stopped: %2</source>
        <translation>电机 %1：无法确认是否已停止：%2</translation>
    </message>
    <message>
        <source>Motor %1 is possibly still running (%2). The stop goes out as soon as the link is back; if needed now, use the machine&apos;s own emergency stop.</source>
        <translation>电机 %1 可能仍在运行（%2）。通信恢复后将立即发送停止命令；如需立即停止，请使用机器自身的急停。</translation>
    </message>
    <message>
        <source>the link was lost while it moved: %1</source>
        <translation>运行中通信中断：%1</translation>
    </message>
    <message>
        <source>The link is back: stopping motor %1, which was possibly still running</source>
        <translation>通信已恢复：正在停止可能仍在运行的电机 %1</translation>
    </message>
    <message>
        <source>link back</source>
        <translation>通信恢复</translation>
    </message>
    <message>
        <source>Motor %1: jog %2 not done: %3</source>
        <translation>电机 %1：%2点动未执行：%3</translation>
    </message>
    <message>
        <source>E-STOP</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>another hand took over from the pad</source>
        <translation>另一操作接管了手柄的点动</translation>
    </message>
    <message>
        <source>Motor %1 was jogged from the pad: it stops; press again to jog it here</source>
        <translation>电机 %1 正由手柄点动：现在停止；请再按一次在此点动</translation>
    </message>
</context>
<context>
    <name>stepcom::JogPanel</name>
    <message>
        <source>stop button</source>
        <translation>停止按钮</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>未连接。</translation>
    </message>
    <message>
        <source>Not read yet: %1.</source>
        <translation>尚未读取：%1。</translation>
    </message>
    <message>
        <source>%1 edited but not written: the controller moves by the values it holds. Write or revert the edit first.</source>
        <translation>%1 已修改但尚未写入：控制器按其中保存的值运行。请先写入或还原该修改。</translation>
    </message>
    <message>
        <source>The motor is moving.</source>
        <translation>电机正在运行。</translation>
    </message>
    <message>
        <source>This controller has no single move.</source>
        <translation>此控制器没有单次运行功能。</translation>
    </message>
    <message>
        <source>%1, %2, at %3</source>
        <translation>%1，%2，%3</translation>
    </message>
    <message>
        <source>Jogging forward</source>
        <translation>正向点动中</translation>
    </message>
    <message>
        <source>Jogging in reverse</source>
        <translation>反向点动中</translation>
    </message>
    <message>
        <source>Stopping…</source>
        <translation>正在停止…</translation>
    </message>
    <message>
        <source>STILL RUNNING after its stop: use the E-STOP</source>
        <translation>停止后仍在运行！请按急停</translation>
    </message>
    <message>
        <source>Possibly still running: the link was lost; the stop goes out when it is back</source>
        <translation>可能仍在运行：通信已中断；通信恢复后将发送停止命令</translation>
    </message>
    <message>
        <source>%1… running</source>
        <translation>%1… 运行中</translation>
    </message>
    <message>
        <source>%1…</source>
        <translation>%1…</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <source>Idle</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Idle — %1</source>
        <translation>停止 — %1</translation>
    </message>
    <message>
        <source>Jogs at %1, the controller&apos;s value, until you apply %2.</source>
        <translation>当前按控制器中的 %1 点动，应用后改为 %2。</translation>
    </message>
    <message>
        <source>Move once by the distance shown, in the direction and at the speed shown (coil %1)</source>
        <translation>按显示的距离、方向和速度运行一次（线圈 %1）</translation>
    </message>
    <message>
        <source>No home input: runs in reverse until a limit or a stop, without zeroing.</source>
        <translation>未设定原点信号：一直反转，直到碰到限位或收到停止命令，坐标不清零。</translation>
    </message>
    <message>
        <source>Reverse until %1, then position 0.</source>
        <translation>反转至 %1 有效，坐标归 0。</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>◀ Reverse</source>
        <translation>◀ 反转</translation>
    </message>
    <message>
        <source>Forward ▶</source>
        <translation>正转 ▶</translation>
    </message>
    <message>
        <source>Hold to run motor %1 in reverse; let go to stop</source>
        <translation>按住时电机 %1 反转，松开即停止</translation>
    </message>
    <message>
        <source>Hold to run motor %1 forward; let go to stop</source>
        <translation>按住时电机 %1 正转，松开即停止</translation>
    </message>
    <message>
        <source>Stop motor &amp;%1</source>
        <translation>停止电机 &amp;%1</translation>
    </message>
    <message>
        <source>Stop motor %1 at once, whatever started it</source>
        <translation>立即停止电机 %1，无论是由什么启动的</translation>
    </message>
    <message>
        <source>Jog speed:</source>
        <translation>点动速度：</translation>
    </message>
    <message>
        <source>&amp;Apply speed</source>
        <translation>应用速度(&amp;A)</translation>
    </message>
    <message>
        <source>Single move:</source>
        <translation>单次运行：</translation>
    </message>
    <message>
        <source>&amp;Single move</source>
        <translation>单次运行(&amp;S)</translation>
    </message>
    <message>
        <source>Home:</source>
        <translation>回机械零：</translation>
    </message>
    <message>
        <source>Home &amp;motor %1</source>
        <translation>电机 %1 回机械零(&amp;M)</translation>
    </message>
    <message>
        <source>Run motor %1 in reverse to its home input and set its position to 0</source>
        <translation>电机 %1 反转到原点信号处，并将其坐标设为 0</translation>
    </message>
    <message>
        <source>Reference: %1</source>
        <translation>参考点：%1</translation>
    </message>
    <message>
        <source>Write just the jog speed to the controller: the write dialog shows it first, then it is written and read back. The controller takes a new speed even while the motor runs. Other edits wait for &quot;Write changes&quot;.</source>
        <translation>只将点动速度写入控制器：先在写入对话框中显示，然后写入并回读。电机运行中控制器也会采用新速度。其他修改需通过“写入更改”写入。</translation>
    </message>
</context>
<context>
    <name>stepcom::LineHub</name>
    <message>
        <source>the line is already open</source>
        <translation>线路已打开</translation>
    </message>
    <message>
        <source>a line needs at least one party, not %1</source>
        <translation>线路至少需要一个端口，而不是 %1</translation>
    </message>
    <message>
        <source>cannot make a pseudo-terminal: %1</source>
        <translation>无法创建伪终端：%1</translation>
    </message>
    <message>
        <source>a line of pseudo-terminals needs Unix</source>
        <translation>伪终端线路需要 Unix 系统</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <source>no party %1 on the line</source>
        <translation>线路上没有端口 %1</translation>
    </message>
    <message>
        <source>%1 exists and is not a symlink: not replaced</source>
        <translation>%1 已存在且不是符号链接：未替换</translation>
    </message>
    <message>
        <source>cannot make the symlink %1</source>
        <translation>无法创建符号链接 %1</translation>
    </message>
</context>
<context>
    <name>stepcom::LineOptionsBox</name>
    <message>
        <source>Line and adapter</source>
        <translation>线路与适配器</translation>
    </message>
    <message>
        <source>&amp;Answer delay:</source>
        <translation>应答延时(&amp;A)：</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>T&amp;urnaround:</source>
        <translation>转换间隔(&amp;U)：</translation>
    </message>
    <message>
        <source>Extra silence after an answer before the next request, for converters that need it</source>
        <translation>收到应答后、发送下一个请求前额外的静默时间，供需要它的转换器使用</translation>
    </message>
    <message>
        <source>The adapter &amp;echoes what it sends</source>
        <translation>适配器会回显发送的数据(&amp;E)</translation>
    </message>
    <message>
        <source>How long the controller may take to answer (its manual: 35 ms): the least the timeout is fitted to. Answers are judged by what they say, however soon they come</source>
        <translation>控制器可能需要多长时间应答（说明书：35 ms）：自适应超时的下限。无论应答多快到达，都按其内容判断</translation>
    </message>
    <message>
        <source>For half-duplex USB-RS485 adapters without echo suppression: the request&apos;s own bytes are skipped from the first request on. Without it StepCom finds the echo on the first read</source>
        <translation>用于没有回显抑制的半双工 USB-RS485 适配器：从第一个请求起跳过请求自身的字节。不勾选时，StepCom 在第一次读取时发现回显</translation>
    </message>
    <message>
        <source>This adapter echoes what it sends: StepCom found the request&apos;s own bytes before the answers and skips them. Remember it for this port?</source>
        <translation>此适配器会回显发送的数据：StepCom 在应答之前发现了请求自身的字节，并跳过它们。为此端口记住这一点吗？</translation>
    </message>
    <message>
        <source>Remember echo</source>
        <translation>记住回显</translation>
    </message>
    <message>
        <source>&amp;RS-485 direction:</source>
        <translation>RS-485 收发方向(&amp;R)：</translation>
    </message>
    <message>
        <source>the adapter switches by itself</source>
        <translation>适配器自动切换</translation>
    </message>
    <message>
        <source>the driver&apos;s RS-485 mode (RTS on send)</source>
        <translation>驱动的 RS-485 模式（发送时置 RTS）</translation>
    </message>
    <message>
        <source>StepCom switches RTS</source>
        <translation>由 StepCom 切换 RTS</translation>
    </message>
    <message>
        <source>Who switches an RS-485 adapter between sending and receiving. Most adapters do it themselves; some converters need RTS. A driver that refuses is named when connecting, and nothing is sent</source>
        <translation>由谁切换 RS-485 适配器的发送与接收。大多数适配器自动切换；有些转换器需要 RTS。驱动拒绝时，连接时会指明该驱动，并且不发送任何数据</translation>
    </message>
</context>
<context>
    <name>stepcom::LinkHealth</name>
    <message>
        <source>Port closed</source>
        <translation>端口已关闭</translation>
    </message>
    <message>
        <source>Opening the port…</source>
        <translation>正在打开端口…</translation>
    </message>
    <message>
        <source>Port open, waiting for the controller…</source>
        <translation>端口已打开，正在等待控制器…</translation>
    </message>
    <message>
        <source>Not answering</source>
        <translation>无应答</translation>
    </message>
    <message>
        <source>Connected</source>
        <translation>已连接</translation>
    </message>
    <message>
        <source>The port is open but no controller answers. Likely causes: another device id (factory: 1), another baud rate (factory: 9600) or parity (factory: none), the RS-485 wires A and B swapped, or the controller has no power. A bus scan tries the ids and baud rates for you.</source>
        <translation>端口已打开，但没有控制器应答。可能的原因：设备地址不同（出厂：1）、波特率不同（出厂：9600）或校验位不同（出厂：无）、RS-485 的 A、B 线接反，或控制器没有上电。总线扫描可以替您逐一尝试地址和波特率。</translation>
    </message>
</context>
<context>
    <name>stepcom::LinkSettings</name>
    <message>
        <source>device id %1 is outside 1-255</source>
        <translation>设备 ID %1 超出范围 1-255</translation>
    </message>
    <message>
        <source>timeout %1 ms is outside 20-60000 ms</source>
        <translation>超时 %1 ms 超出范围 20-60000 ms</translation>
    </message>
    <message>
        <source>retries %1 is outside 0-10</source>
        <translation>重试次数 %1 超出范围 0-10</translation>
    </message>
    <message>
        <source>no host given</source>
        <translation>未指定主机</translation>
    </message>
    <message>
        <source>TCP port %1 is outside 1-65535</source>
        <translation>TCP 端口 %1 超出范围 1-65535</translation>
    </message>
    <message>
        <source>no serial port given</source>
        <translation>未指定串口</translation>
    </message>
    <message>
        <source>baud %1 is not one of 4800, 9600, 19200, 38400</source>
        <translation>波特率 %1 不是 4800、9600、19200、38400 之一</translation>
    </message>
    <message>
        <source>stop bits must be 1 or 2</source>
        <translation>停止位必须为 1 或 2</translation>
    </message>
    <message>
        <source>%1:%2 · id %3</source>
        <translation>%1:%2 · 站号 %3</translation>
    </message>
    <message>
        <source>%1 · %2 8%3%4 · id %5</source>
        <translation>%1 · %2 8%3%4 · 站号 %5</translation>
    </message>
    <message>
        <source>%1:%2 (RTU over TCP) · id %3</source>
        <translation>%1:%2（TCP 上的 RTU）· 站号 %3</translation>
    </message>
    <message>
        <source>answer delay %1 ms is outside 0-1000 ms</source>
        <translation>应答延时 %1 ms 超出 0-1000 ms</translation>
    </message>
    <message>
        <source>turnaround %1 ms is outside 0-1000 ms</source>
        <translation>转换间隔 %1 ms 超出 0-1000 ms</translation>
    </message>
    <message>
        <source>the answer delay (%1 ms) must be shorter than the timeout (%2 ms)</source>
        <translation>应答延时（%1 ms）必须短于超时（%2 ms）</translation>
    </message>
    <message>
        <source>RS-485 delays %1/%2 us are outside 0-100000 us</source>
        <translation>RS-485 延时 %1/%2 us 超出 0-100000 us</translation>
    </message>
</context>
<context>
    <name>stepcom::LinkStats</name>
    <message>
        <source>; suggested timeout %1 ms (now %2 ms)</source>
        <translation>；建议超时 %1 ms（当前 %2 ms）</translation>
    </message>
    <message>
        <source>no answer timed yet</source>
        <translation>尚未测得应答时间</translation>
    </message>
    <message>
        <source>answers in %1</source>
        <translation>应答时间 %1</translation>
    </message>
    <message>
        <source>echo not known yet</source>
        <translation>尚不知道是否回显</translation>
    </message>
    <message>
        <source>the adapter echoes</source>
        <translation>适配器会回显</translation>
    </message>
    <message>
        <source>no echo</source>
        <translation>无回显</translation>
    </message>
    <message>
        <source>timeout %1 ms</source>
        <translation>超时 %1 ms</translation>
    </message>
    <message>
        <source>%1 requests, %2 answers; %3 timeouts, %4 CRC errors, %5 exceptions, %6 stale or foreign answers discarded</source>
        <translation>%1 个请求，%2 个应答；%3 次超时，%4 次 CRC 错误，%5 次异常，丢弃 %6 个过时或无关的应答</translation>
    </message>
    <message>
        <source>line: %1</source>
        <translation>线路：%1</translation>
    </message>
</context>
<context>
    <name>stepcom::LinkStatus</name>
    <message>
        <source>Connected (simulator)</source>
        <translation>已连接（仿真器）</translation>
    </message>
    <message>
        <source>Connected</source>
        <translation>已连接</translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation>正在连接…</translation>
    </message>
    <message>
        <source>Disconnected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>⚠ Not saved to flash</source>
        <translation>⚠ 未保存到闪存</translation>
    </message>
    <message>
        <source>Parameters were written but not saved to the controller&apos;s flash: they are lost when it loses power. Use Save to flash.</source>
        <translation>参数已写入，但尚未保存到控制器的闪存：控制器断电后将丢失。请使用“保存到闪存”。</translation>
    </message>
    <message>
        <source>Not answering</source>
        <translation>无应答</translation>
    </message>
    <message>
        <source>Port open, waiting for an answer…</source>
        <translation>端口已打开，正在等待应答…</translation>
    </message>
    <message>
        <source>errors: %1 (timeouts %2, CRC %3, exceptions %4, stale answers %5)</source>
        <translation>错误：%1（超时 %2，CRC %3，异常 %4，过时应答 %5）</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Stop trying to reconnect; Connect tries again</source>
        <translation>停止重新连接；按“连接”可再次尝试</translation>
    </message>
    <message>
        <source>Link lost — reconnecting in %1 s (attempt %2)</source>
        <translation>连接丢失 — %1 秒后重新连接（第 %2 次尝试）</translation>
    </message>
    <message>
        <source>Link lost — reconnecting… (attempt %1)</source>
        <translation>连接丢失 — 正在重新连接…（第 %1 次尝试）</translation>
    </message>
    <message>
        <source>Line: %1 (at most %2 ms)</source>
        <translation>线路：%1（最多 %2 ms）</translation>
    </message>
    <message>
        <source>%1 transactions/s</source>
        <translation>%1 次通信/s</translation>
    </message>
</context>
<context>
    <name>stepcom::ListenLog</name>
    <message>
        <source>cannot write the session log %1: %2</source>
        <translation>无法写入会话日志 %1：%2</translation>
    </message>
    <message>
        <source>%1 %2 baud, listening (another master drives the line)</source>
        <translation>%1 %2 波特率，监听（由另一个主站驱动线路）</translation>
    </message>
</context>
<context>
    <name>stepcom::ListenMode</name>
    <message>
        <source>Listening needs the window free: disconnect, and close any profile file or replay first.</source>
        <translation>监听需要窗口空闲：请先断开连接，并关闭所有参数文件或回放。</translation>
    </message>
    <message>
        <source>Listening hears a serial line: choose its port on the Connection page.</source>
        <translation>监听针对串口线路：请在连接页面选择其端口。</translation>
    </message>
    <message>
        <source>Cannot listen on %1: %2</source>
        <translation>无法在 %1 上监听：%2</translation>
    </message>
    <message>
        <source>Listening ended: the port %1 was lost: %2</source>
        <translation>监听已结束：端口 %1 已断开：%2</translation>
    </message>
    <message>
        <source>E-STOP into the other master&apos;s line (try %1)</source>
        <translation>向另一个主站的线路发送急停（第 %1 次）</translation>
    </message>
    <message>
        <source>listening on %1 at %2 baud: another master drives the line, StepCom sends nothing</source>
        <translation>正在 %1 上以 %2 波特率监听：由另一个主站驱动线路，StepCom 不发送任何数据</translation>
    </message>
    <message>
        <source>heard on %1</source>
        <translation>在 %1 上听到</translation>
    </message>
    <message>
        <source>Stop listening</source>
        <translation>停止监听</translation>
    </message>
    <message>
        <source>listening ended</source>
        <translation>监听已结束</translation>
    </message>
    <message>
        <source>PLC (heard)</source>
        <translation>PLC（听到）</translation>
    </message>
    <message>
        <source>listening on %1</source>
        <translation>正在 %1 上监听</translation>
    </message>
    <message>
        <source>E-STOP</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>Send E-STOP</source>
        <translation>发送急停</translation>
    </message>
    <message>
        <source>The E-STOP could not be sent on %1</source>
        <translation>无法在 %1 上发送急停</translation>
    </message>
    <message>
        <source>E-STOP sent into a line driven by another master</source>
        <translation>急停已发送到由另一个主站驱动的线路</translation>
    </message>
    <message>
        <source>&lt;b&gt;Listening on %1&lt;/b&gt; — another master drives the line. The values shown are the ones last heard in its traffic with id %2, not read by StepCom; a value never heard is unknown. Nothing is written, jogged or polled; the E-STOP asks first. The other master&apos;s writes (%3):</source>
        <translation>&lt;b&gt;正在 %1 上监听&lt;/b&gt;——由另一个主站驱动线路。显示的值是在它与站号 %2 的通信中最后听到的值，并非 StepCom 读取；从未听到的值为未知。不写入、不点动、不轮询；急停会先询问。另一个主站的写入（%3）：</translation>
    </message>
    <message>
        <source>Listen only (another master drives the line)</source>
        <translation>仅监听（由另一个主站驱动线路）</translation>
    </message>
    <message>
        <source>The other master&apos;s writes</source>
        <translation>另一个主站的写入</translation>
    </message>
    <message>
        <source>the controller&apos;s motion state read back after the E-STOP (try %1)</source>
        <translation>急停后回读控制器的运动状态（第 %1 次）</translation>
    </message>
    <message>
        <source>The adapter on %1 returns what StepCom sends (an echo), but the line&apos;s echo option is off: StepCom&apos;s own E-STOP was not taken for the controller&apos;s answer. Tick &quot;The adapter echoes what it sends&quot; for this line on the Connection page.</source>
        <translation>%1 上的适配器会返回 StepCom 发送的内容（回显），但该线路的回显选项是关闭的：StepCom 自己的急停没有被当作控制器的应答。请在连接页面为该线路勾选“适配器会回显发送的数据”。</translation>
    </message>
    <message>
        <source>Another master drives this line. Send the E-STOP to id %1 into its traffic? It goes in the first silence and again until the controller answers it and its motors are read back stopped.</source>
        <translation>另一个主站正在驱动此线路。要把急停发送给 ID %1，插入它的通信中吗？急停在第一个静默中发出，并重复发送，直到控制器应答且回读到电机已停止。</translation>
    </message>
</context>
<context>
    <name>stepcom::LostStepResult</name>
    <message>
        <source>kept its steps</source>
        <translation>未丢步</translation>
    </message>
    <message>
        <source>lost steps</source>
        <translation>丢步</translation>
    </message>
    <message>
        <source>not known</source>
        <translation>无法判断是否丢步</translation>
    </message>
</context>
<context>
    <name>stepcom::MachineActions</name>
    <message>
        <source>Apply profile to &amp;several devices…</source>
        <translation>将参数文件应用到多台设备(&amp;S)…</translation>
    </message>
    <message>
        <source>Compare one profile file with several devices of the line, then write the checked differences to each and verify them</source>
        <translation>将一个参数文件与总线上的多台设备比较，然后把勾选的不同之处写入每台设备并校验</translation>
    </message>
    <message>
        <source>Save &amp;all devices as profiles…</source>
        <translation>将所有设备保存为参数文件(&amp;A)…</translation>
    </message>
    <message>
        <source>Read every device of the line and save each as a profile file into one folder</source>
        <translation>读取总线上的每台设备，并分别保存为参数文件到同一个文件夹</translation>
    </message>
    <message>
        <source>Commissioning report of the &amp;machine…</source>
        <translation>整机调试报告(&amp;M)…</translation>
    </message>
    <message>
        <source>Read every device of the line, then write one commissioning report of them all</source>
        <translation>读取总线上的每台设备，然后生成一份包含全部设备的调试报告</translation>
    </message>
    <message>
        <source>Apply a profile to several devices</source>
        <translation>将参数文件应用到多台设备</translation>
    </message>
    <message>
        <source>StepCom profiles (*.json);;All files (*)</source>
        <translation>StepCom 参数文件 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>The profile cannot be used: nothing was written</source>
        <translation>无法使用该参数文件：未写入任何数据</translation>
    </message>
    <message>
        <source>%1: connect to the line first, and wait for what runs</source>
        <translation>%1：请先连接总线，并等待正在进行的操作结束</translation>
    </message>
    <message>
        <source>id %1: %2</source>
        <translation>ID %1：%2</translation>
    </message>
    <message numerus="yes">
        <source>%1: reading %n device(s)</source>
        <translation>
            <numerusform>%1：正在读取 %n 台设备</numerusform>
        </translation>
    </message>
    <message>
        <source>Folder for the profiles of every device</source>
        <translation>保存每台设备参数文件的文件夹</translation>
    </message>
    <message>
        <source>Nothing was saved: %1</source>
        <translation>未保存任何内容：%1</translation>
    </message>
    <message>
        <source>Save all devices</source>
        <translation>保存所有设备</translation>
    </message>
    <message>
        <source>id %1 was not saved: it could not be read completely</source>
        <translation>ID %1 未保存：无法完整读取</translation>
    </message>
    <message>
        <source>id %1 saved to %2</source>
        <translation>ID %1 已保存到 %2</translation>
    </message>
    <message>
        <source>id %1 was not saved: %2</source>
        <translation>ID %1 未保存：%2</translation>
    </message>
    <message>
        <source>Commissioning report of the machine</source>
        <translation>整机调试报告</translation>
    </message>
    <message>
        <source>Notes for the report (machine, place, who commissioned it):</source>
        <translation>报告备注（机器、地点、调试人员）：</translation>
    </message>
    <message>
        <source>Save the commissioning report of the machine</source>
        <translation>保存整机调试报告</translation>
    </message>
    <message>
        <source>PDF (*.pdf);;HTML (*.html)</source>
        <translation>PDF (*.pdf);;HTML (*.html)</translation>
    </message>
    <message>
        <source>Commissioning report</source>
        <translation>调试报告</translation>
    </message>
    <message>
        <source>No report: not every device could be read completely</source>
        <translation>未生成报告：并非每台设备都能完整读取</translation>
    </message>
    <message numerus="yes">
        <source>Commissioning report of %n device(s) written to %1</source>
        <translation>
            <numerusform>已将 %n 台设备的调试报告写入 %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stepcom::MachineFile</name>
    <message>
        <source>%1: cannot read the machine file: %2</source>
        <translation>%1：无法读取机器文件：%2</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>not JSON (%1 at offset %2)</source>
        <translation>不是 JSON（%1，位于偏移 %2）</translation>
    </message>
    <message>
        <source>not a JSON object</source>
        <translation>不是 JSON 对象</translation>
    </message>
    <message>
        <source>format: must be &quot;stepcom-sim-machine&quot;</source>
        <translation>format：必须是 &quot;stepcom-sim-machine&quot;</translation>
    </message>
    <message>
        <source>version: must be 1</source>
        <translation>version：必须是 1</translation>
    </message>
    <message>
        <source>%1: unknown key (the axes are motor1, motor2, ...)</source>
        <translation>%1：未知的键（轴的名称是 motor1、motor2……）</translation>
    </message>
    <message>
        <source>%1: must be an object</source>
        <translation>%1：必须是对象</translation>
    </message>
</context>
<context>
    <name>stepcom::MachineReport</name>
    <message numerus="yes">
        <source>Commissioning report of a machine: %n controller(s)</source>
        <translation>
            <numerusform>整机调试报告：%n 台控制器</numerusform>
        </translation>
    </message>
    <message>
        <source>Controller id %1</source>
        <translation>控制器 ID %1</translation>
    </message>
    <message>
        <source>Controller id %1: %2</source>
        <translation>控制器 ID %1：%2</translation>
    </message>
    <message>
        <source>Controllers on the line</source>
        <translation>总线上的控制器</translation>
    </message>
    <message>
        <source>Device id</source>
        <translation>设备 ID</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Settings fingerprint</source>
        <translation>设置指纹</translation>
    </message>
    <message>
        <source>Date: %1</source>
        <translation>日期：%1</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>%1: no controller to report on</source>
        <translation>%1：没有可报告的控制器</translation>
    </message>
    <message>
        <source>%1 -- simulator, not a machine</source>
        <translation>%1 —— 仿真器，不是真实机器</translation>
    </message>
    <message>
        <source>built-in simulator -- not a machine</source>
        <translation>内置仿真器 —— 不是真实机器</translation>
    </message>
</context>
<context>
    <name>stepcom::MachineStrip</name>
    <message>
        <source>idle</source>
        <translation>空闲</translation>
    </message>
    <message>
        <source>running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <source>at a limit</source>
        <translation>停在限位</translation>
    </message>
    <message>
        <source>Motor %1: %2</source>
        <translation>电机 %1：%2</translation>
    </message>
    <message>
        <source>referenced</source>
        <translation>已建立参考点</translation>
    </message>
    <message>
        <source>not referenced</source>
        <translation>未建立参考点</translation>
    </message>
    <message>
        <source>Motor %1 position: %2</source>
        <translation>电机 %1 位置：%2</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>on</source>
        <translation>开</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关</translation>
    </message>
    <message>
        <source>port closed</source>
        <translation>端口已关闭</translation>
    </message>
    <message>
        <source>asking…</source>
        <translation>询问中…</translation>
    </message>
    <message>
        <source>not answering</source>
        <translation>无应答</translation>
    </message>
    <message>
        <source>answering</source>
        <translation>有应答</translation>
    </message>
    <message>
        <source>Link: %1</source>
        <translation>链路：%1</translation>
    </message>
    <message>
        <source>Line: %1</source>
        <translation>线路：%1</translation>
    </message>
    <message>
        <source>Device %1</source>
        <translation>设备 %1</translation>
    </message>
    <message>
        <source>%1 (id %2)</source>
        <translation>%1（地址 %2）</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>Motor %1 position</source>
        <translation>电机 %1 位置</translation>
    </message>
    <message>
        <source>IN 1-%1</source>
        <translation>输入 1-%1</translation>
    </message>
    <message>
        <source>OUT 1-%1</source>
        <translation>输出 1-%1</translation>
    </message>
    <message>
        <source>reference not known</source>
        <translation>参考点未知</translation>
    </message>
</context>
<context>
    <name>stepcom::MainWindow</name>
    <message>
        <source>About StepCom</source>
        <translation>关于 StepCom</translation>
    </message>
    <message>
        <source>&lt;b&gt;StepCom %1&lt;/b&gt;&lt;br&gt;Commissioning tool for 2-axis stepper controllers over Modbus RTU/TCP.&lt;br&gt;GPL-3.0-or-later.</source>
        <translation>&lt;b&gt;StepCom %1&lt;/b&gt;&lt;br&gt;通过 Modbus RTU/TCP 调试两轴步进电机控制器的工具。&lt;br&gt;许可证：GPL-3.0-or-later。</translation>
    </message>
    <message>
        <source>&amp;Read all</source>
        <translation>读取全部(&amp;R)</translation>
    </message>
    <message>
        <source>Read every parameter from the controller (%1)</source>
        <translation>从控制器读取所有参数（%1）</translation>
    </message>
    <message>
        <source>&amp;Write changes…</source>
        <translation>写入更改(&amp;W)…</translation>
    </message>
    <message>
        <source>Show the edited values, then write them and verify (%1)</source>
        <translation>显示已修改的值，确认后写入并验证（%1）</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>还原(&amp;V)</translation>
    </message>
    <message>
        <source>Drop every edit and show what the controller holds</source>
        <translation>放弃所有修改，显示控制器中的值</translation>
    </message>
    <message>
        <source>&amp;Save to flash</source>
        <translation>保存到闪存(&amp;S)</translation>
    </message>
    <message>
        <source>Save the controller&apos;s parameters to its non-volatile memory (coil 00096)</source>
        <translation>将控制器参数保存到其非易失性存储器（线圈 00096）</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>断开(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Emergency stop</source>
        <translation>急停(&amp;E)</translation>
    </message>
    <message>
        <source>All motors and outputs off, at once (key: %1)</source>
        <translation>立即停止所有电机并关闭所有输出（快捷键：%1）</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;About StepCom</source>
        <translation>关于 StepCom(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Device</source>
        <translation>设备(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>主工具栏</translation>
    </message>
    <message>
        <source>Traffic</source>
        <translation>通信报文</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>消息</translation>
    </message>
    <message>
        <source>Unwritten changes</source>
        <translation>未写入的更改</translation>
    </message>
    <message numerus="yes">
        <source>%n edited value(s) were never written to the controller. Close anyway and lose them?</source>
        <translation>
            <numerusform>有 %n 个已修改的值尚未写入控制器。仍要关闭并放弃这些修改吗？</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n edited value(s) of %1 are not saved in the file. Close anyway and lose them?</source>
        <translation>
            <numerusform>%1 中有 %n 个修改过的值尚未保存到文件。仍然关闭并放弃这些修改吗？</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;User guide</source>
        <translation>使用手册(&amp;U)</translation>
    </message>
    <message>
        <source>The user guide at the section about this page (%1)</source>
        <translation>打开使用手册中介绍本页面的章节（%1）</translation>
    </message>
    <message>
        <source>What&apos;s &amp;this?</source>
        <translation>这是什么？(&amp;T)</translation>
    </message>
    <message>
        <source>%1%2 — profile file, no controller</source>
        <translation>%1%2 — 参数文件，未连接控制器</translation>
    </message>
    <message>
        <source>%1 — replay, no controller</source>
        <translation>%1 — 回放，无控制器</translation>
    </message>
    <message>
        <source>Create &amp;support bundle…</source>
        <translation>创建支持包(&amp;S)…</translation>
    </message>
    <message>
        <source>One .zip file with the session logs, the profile and the settings, to send to support</source>
        <translation>一个包含会话日志、参数文件和设置的 .zip 文件，用于发给技术支持</translation>
    </message>
    <message>
        <source>Open a file</source>
        <translation>打开文件</translation>
    </message>
    <message>
        <source>Use %1 rpm…</source>
        <translation>使用 %1 rpm…</translation>
    </message>
    <message>
        <source>Find a safe speed…</source>
        <translation>寻找安全速度…</translation>
    </message>
    <message>
        <source>Motor %1 lost steps at %2 rpm</source>
        <translation>电机 %1 在 %2 rpm 时丢步</translation>
    </message>
</context>
<context>
    <name>stepcom::MarginFinder</name>
    <message>
        <source>Motor %1: the acceleration margin at %2 rpm: the lost-step test (%3 cycle(s) of %4 %5 each way) at each acceleration %6 %7, stopping at the first loss</source>
        <translation>电机 %1：%2 rpm 下的加速度余量：在每个加速度（%6 %7）下运行丢步测试（%3 个循环，每个方向 %4 %5），遇到第一次丢步即停止</translation>
    </message>
    <message>
        <source>Motor %1: the speed margin: the lost-step test (%3 cycle(s) of %4 %5 each way) at each speed %6 %7, stopping at the first loss</source>
        <translation>电机 %1：转速余量：在每个转速（%6 %7）下运行丢步测试（%3 个循环，每个方向 %4 %5），遇到第一次丢步即停止</translation>
    </message>
    <message>
        <source>  each test references on the home switch (IN%1) and moves up to %2 %3 past it</source>
        <translation>  每次测试都以原点开关（IN%1）为参考，最远移动到越过它 %2 %3 处</translation>
    </message>
    <message>
        <source>  afterwards: speed %1 rpm and acceleration %2 put back and verified; nothing of the recommendation is written</source>
        <translation>  之后：恢复速度 %1 rpm 和加速度 %2 并校验；不写入任何推荐值</translation>
    </message>
    <message>
        <source>Motor %1: %2 %3: %4</source>
        <translation>电机 %1：%2 %3：%4</translation>
    </message>
    <message>
        <source>the search must go up: from %1 is above to %2</source>
        <translation>搜索必须由低到高：起始值 %1 高于终止值 %2</translation>
    </message>
    <message>
        <source>the step must be at least 1, not %1</source>
        <translation>步长至少为 1，不能是 %1</translation>
    </message>
    <message>
        <source>%1 values to test: take a larger step (at most 100)</source>
        <translation>要测试 %1 个值：请取更大的步长（最多 100 个值）</translation>
    </message>
    <message>
        <source>Motor %1: testing %2 %3 (%4 of %5)</source>
        <translation>电机 %1：正在测试 %2 %3（第 %4 个，共 %5 个）</translation>
    </message>
    <message>
        <source>Stopped before anything moved</source>
        <translation>在任何运动之前已停止</translation>
    </message>
    <message>
        <source>Motor %1 kept its steps up to %2 %3 and lost them at %4 %3: run at %5 %3 or less</source>
        <translation>电机 %1 在 %2 %3 及以下未丢步，在 %4 %3 时丢步：请以 %5 %3 或更低运行</translation>
    </message>
    <message>
        <source>Motor %1 kept its steps at every value up to %2 %3: run at %4 %3 or less</source>
        <translation>电机 %1 在直到 %2 %3 的每个值下都未丢步：请以 %4 %3 或更低运行</translation>
    </message>
    <message>
        <source>Motor %1 lost steps already at %2 %3, the lowest value tested</source>
        <translation>电机 %1 在所测试的最低值 %2 %3 时就已丢步</translation>
    </message>
</context>
<context>
    <name>stepcom::MarginPlot</name>
    <message>
        <source>kept its steps</source>
        <translation>未丢步</translation>
    </message>
    <message>
        <source>lost steps</source>
        <translation>丢步</translation>
    </message>
    <message>
        <source>recommended</source>
        <translation>推荐值</translation>
    </message>
    <message>
        <source>Acceleration (Hz/ms)</source>
        <translation>加速度 (Hz/ms)</translation>
    </message>
    <message>
        <source>Speed (rpm)</source>
        <translation>速度 (rpm)</translation>
    </message>
    <message>
        <source>Lost (mm)</source>
        <translation>丢失量 (mm)</translation>
    </message>
</context>
<context>
    <name>stepcom::MessageView</name>
    <message>
        <source>C&amp;lear messages</source>
        <translation>清除消息(&amp;L)</translation>
    </message>
</context>
<context>
    <name>stepcom::Modbus</name>
    <message>
        <source>illegal function</source>
        <translation>非法功能</translation>
    </message>
    <message>
        <source>illegal data address</source>
        <translation>非法数据地址</translation>
    </message>
    <message>
        <source>illegal data value</source>
        <translation>非法数据值</translation>
    </message>
    <message>
        <source>server device failure</source>
        <translation>从站设备故障</translation>
    </message>
    <message>
        <source>acknowledge</source>
        <translation>确认</translation>
    </message>
    <message>
        <source>server device busy</source>
        <translation>从站设备忙</translation>
    </message>
    <message>
        <source>exception %1</source>
        <translation>异常 %1</translation>
    </message>
</context>
<context>
    <name>stepcom::ModbusLink</name>
    <message>
        <source>no connection to %1 within %2 s</source>
        <translation>%2 s 内未能连接到 %1</translation>
    </message>
    <message>
        <source>reconnecting</source>
        <translation>正在重新连接</translation>
    </message>
    <message>
        <source>serial port %1 does not exist (is the adapter plugged in?)</source>
        <translation>串口 %1 不存在（转换器是否已插好？）</translation>
    </message>
    <message>
        <source>no permission to open %1: add your user to the group that owns it (on Debian and Ubuntu: sudo usermod -aG dialout $USER), then log out and in again</source>
        <translation>没有打开 %1 的权限：请将当前用户加入该设备所属的用户组（Debian 和 Ubuntu 上执行：sudo usermod -aG dialout $USER），然后注销并重新登录</translation>
    </message>
    <message>
        <source>connecting to %1</source>
        <translation>正在连接 %1</translation>
    </message>
    <message>
        <source>cannot open %1</source>
        <translation>无法打开 %1</translation>
    </message>
    <message>
        <source>connected to %1</source>
        <translation>已连接到 %1</translation>
    </message>
    <message>
        <source>connection closed</source>
        <translation>连接已关闭</translation>
    </message>
    <message>
        <source>the port reported an error</source>
        <translation>端口报告错误</translation>
    </message>
    <message>
        <source>link lost: %1</source>
        <translation>连接中断：%1</translation>
    </message>
    <message>
        <source>link closed</source>
        <translation>通信链路已关闭</translation>
    </message>
    <message>
        <source>disconnected: %1</source>
        <translation>已断开：%1</translation>
    </message>
    <message>
        <source>%1: not done, %2</source>
        <translation>%1：未执行，%2</translation>
    </message>
    <message>
        <source>%1: not connected</source>
        <translation>%1：未连接</translation>
    </message>
    <message>
        <source>%1: cancelled%2</source>
        <translation>%1：已取消%2</translation>
    </message>
    <message>
        <source>%1: could not send: %2</source>
        <translation>%1：无法发送：%2</translation>
    </message>
    <message>
        <source>%1: the controller refused: %2</source>
        <translation>%1：控制器返回异常：%2</translation>
    </message>
    <message>
        <source>%1: answers had a bad checksum (CRC)</source>
        <translation>%1：应答校验错误（CRC）</translation>
    </message>
    <message>
        <source>%1: no answer within %2 ms</source>
        <translation>%1：%2 ms 内无应答</translation>
    </message>
    <message>
        <source> -- the controller may have acted on it</source>
        <translation>（控制器可能已执行该命令）</translation>
    </message>
    <message>
        <source>the port stopped responding (no answer and no timeout from the driver)</source>
        <translation>端口停止响应（驱动程序既无应答也未报告超时）</translation>
    </message>
    <message>
        <source>coil %1</source>
        <translation>线圈 %1</translation>
    </message>
    <message>
        <source>id %1, %2</source>
        <translation>ID %1，%2</translation>
    </message>
    <message>
        <source> (discarded: %1)</source>
        <translation>（已丢弃：%1）</translation>
    </message>
    <message>
        <source>stale/foreign answer discarded: %1</source>
        <translation>已丢弃过时/无关的应答：%1</translation>
    </message>
    <message>
        <source>the adapter echoes what it sends: the request&apos;s own bytes came back before the answer; they are skipped from now on</source>
        <translation>适配器会回显发送的数据：请求自身的字节在应答之前返回；此后跳过它们</translation>
    </message>
    <message>
        <source>the adapter does not echo what it sends (the echo option is on): answers are read without skipping a copy</source>
        <translation>适配器并不回显发送的数据（回显选项已打开）：读取应答时不再跳过副本</translation>
    </message>
    <message>
        <source> -- only the request&apos;s own bytes came back (the adapter&apos;s echo): the controller did not answer</source>
        <translation> —— 只收到了请求自身的字节（适配器的回显）：控制器没有应答</translation>
    </message>
    <message>
        <source> -- it answered %1 s ago: busy (writing its flash?), switched off, or a disturbed line</source>
        <translation> —— 它在 %1 s 前还应答过：正忙（正在写闪存？）、已断电，或线路受到干扰</translation>
    </message>
    <message>
        <source> -- check the device id (%1), the host and port, and the converter&apos;s serial settings; the bus scan finds controllers (the window&apos;s Scan bus, or stepcomctl scan)</source>
        <translation> —— 请检查站号（%1）、主机和端口以及转换器的串口设置；总线扫描可以找到控制器（窗口中的“扫描总线”，或 stepcomctl scan）</translation>
    </message>
    <message>
        <source> -- check the device id (%1), the baud rate and parity (%2), the A/B wiring; the bus scan finds controllers (the window&apos;s Scan bus, or stepcomctl scan)</source>
        <translation> —— 请检查站号（%1）、波特率和校验（%2）以及 A/B 接线；总线扫描可以找到控制器（窗口中的“扫描总线”，或 stepcomctl scan）</translation>
    </message>
    <message>
        <source>adapter: %1</source>
        <translation>适配器：%1</translation>
    </message>
</context>
<context>
    <name>stepcom::ModesPage</name>
    <message>
        <source>Normal operation (factory setting): the motors run from commands (this program, the bus); the inputs are the limits and home inputs chosen in the limit settings.</source>
        <translation>常规模式（出厂设置）：电机由命令（本程序、总线）控制；输入为限位设置中选定的限位和原点输入。</translation>
    </message>
    <message>
        <source>as set in the limit settings</source>
        <translation>按限位设置</translation>
    </message>
    <message>
        <source>Motor 1 only. A start on IN4 runs it forward to the positive limit (IN1), then in reverse to the negative limit (IN2): one round trip, repeated the round-trip count of times (0 = endless). The speed comes from the on-board or external potentiometer.</source>
        <translation>仅电机 1。IN4 启动后正转至正限位 (IN1)，再反转至负限位 (IN2)，为一次往返；按往返次数重复（0 表示无限次）。速度由板载或外接电位器调节。</translation>
    </message>
    <message>
        <source>positive limit</source>
        <translation>正限位</translation>
    </message>
    <message>
        <source>negative limit</source>
        <translation>负限位</translation>
    </message>
    <message>
        <source>emergency stop</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>start (forward)</source>
        <translation>启动（正转）</translation>
    </message>
    <message>
        <source>Motor 1 runs on a short pulse: IN1 starts it (forward the first time), IN2-IN4 stop it and choose the direction of the next start. The limit settings are ignored.</source>
        <translation>电机 1 由短脉冲触发：IN1 启动（首次正转），IN2-IN4 停止并决定下次启动的方向。限位设置失效。</translation>
    </message>
    <message>
        <source>start (forward the first time)</source>
        <translation>启动（首次正转）</translation>
    </message>
    <message>
        <source>stop; next start keeps the direction</source>
        <translation>停止；下次启动保持原方向</translation>
    </message>
    <message>
        <source>stop; next start reverses</source>
        <translation>停止；下次启动反向</translation>
    </message>
    <message>
        <source>stop; next start goes forward</source>
        <translation>停止；下次启动正转</translation>
    </message>
    <message>
        <source>Motor 1 runs forward on a pulse on IN1 and in reverse on a pulse on IN2; IN3 and IN4 are its limits. The limit settings are ignored.</source>
        <translation>IN1 触发电机 1 正转，IN2 触发反转；IN3 和 IN4 为其限位。限位设置失效。</translation>
    </message>
    <message>
        <source>run forward</source>
        <translation>正转运行</translation>
    </message>
    <message>
        <source>run reverse</source>
        <translation>反转运行</translation>
    </message>
    <message>
        <source>positive limit: stops a forward run, only reverse allowed then</source>
        <translation>正限位：停止正转，之后只允许反转</translation>
    </message>
    <message>
        <source>negative limit: stops a reverse run</source>
        <translation>负限位：停止反转</translation>
    </message>
    <message>
        <source>Motor 1 runs while IN1 (forward) or IN2 (reverse) is held and stops when it is released; IN3 and IN4 are its limits. The limit settings are ignored.</source>
        <translation>按住 IN1（正转）或 IN2（反转）时电机 1 运行，松开即停止；IN3 和 IN4 为其限位。限位设置失效。</translation>
    </message>
    <message>
        <source>held: forward; released: stop</source>
        <translation>按住：正转；松开：停止</translation>
    </message>
    <message>
        <source>held: reverse; released: stop</source>
        <translation>按住：反转；松开：停止</translation>
    </message>
    <message>
        <source>Each pulse on IN1 moves motor 1 forward by its set move distance, each pulse on IN2 in reverse; IN3 and IN4 are its limits. The limit settings are ignored.</source>
        <translation>IN1 每触发一次，电机 1 正转设定距离；IN2 每触发一次反转设定距离；IN3 和 IN4 为其限位。限位设置失效。</translation>
    </message>
    <message>
        <source>forward by the set distance</source>
        <translation>正转设定距离</translation>
    </message>
    <message>
        <source>reverse by the set distance</source>
        <translation>反转设定距离</translation>
    </message>
    <message>
        <source>Special modes</source>
        <translation>特殊功能模式</translation>
    </message>
    <message>
        <source>IN%1: %2</source>
        <translation>IN%1：%2</translation>
    </message>
    <message>
        <source>Change the system mode</source>
        <translation>更改系统模式</translation>
    </message>
    <message>
        <source>Change the controller to mode %1 “%2”? This changes what the machine&apos;s inputs IN1-IN4 do, at once.</source>
        <translation>将控制器切换到模式 %1“%2”？这会立即改变机器输入 IN1-IN4 的作用。</translation>
    </message>
    <message>
        <source>Change mode</source>
        <translation>更改模式</translation>
    </message>
    <message>
        <source>The controller&apos;s mode is not known yet.</source>
        <translation>尚未读取控制器的模式。</translation>
    </message>
    <message>
        <source>The controller runs normally.</source>
        <translation>控制器处于常规模式。</translation>
    </message>
    <message>
        <source>The controller is in special mode %1.</source>
        <translation>控制器处于特殊模式 %1。</translation>
    </message>
    <message>
        <source>System mode (40300)</source>
        <translation>系统模式 (40300)</translation>
    </message>
    <message>
        <source>&amp;Mode:</source>
        <translation>模式(&amp;M)：</translation>
    </message>
    <message>
        <source>What the inputs do in each mode (motor 1; short pulses unless “held”)</source>
        <translation>各模式下输入的作用（电机 1；除注明“按住”外均为短脉冲触发）</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>模式</translation>
    </message>
    <message>
        <source>IN1</source>
        <translation>IN1</translation>
    </message>
    <message>
        <source>IN2</source>
        <translation>IN2</translation>
    </message>
    <message>
        <source>IN3</source>
        <translation>IN3</translation>
    </message>
    <message>
        <source>IN4</source>
        <translation>IN4</translation>
    </message>
    <message>
        <source>Limit settings</source>
        <translation>限位设置</translation>
    </message>
    <message>
        <source>ignored</source>
        <translation>失效</translation>
    </message>
    <message>
        <source>used</source>
        <translation>有效</translation>
    </message>
    <message>
        <source>Round trips (40301)</source>
        <translation>往返次数 (40301)</translation>
    </message>
    <message>
        <source>Only used in mode 1 (round trip): how many round trips motor 1 makes after a start; 0 = endless.</source>
        <translation>仅用于模式 1（往返运行）：电机 1 启动后的往返次数；0 表示无限次。</translation>
    </message>
    <message>
        <source>&amp;Write changes…</source>
        <translation>写入更改(&amp;W)…</translation>
    </message>
    <message>
        <source>Modes 2-5 ignore the limit settings: the limit and home inputs set for the motors no longer stop anything. In modes 3-5 only IN3 and IN4 act as limits; in mode 2 nothing does (IN2-IN4 only stop). Wire and test them before using these modes.</source>
        <translation>模式 2-5 忽略限位设置：为电机设置的限位和原点输入不再起作用。模式 3-5 中只有 IN3 和 IN4 作为限位；模式 2 中没有任何限位（IN2-IN4 只用于停止）。使用这些模式前，请先接好并测试这些输入。</translation>
    </message>
    <message>
        <source>The profile file does not set the mode.</source>
        <translation>参数文件中没有设定系统模式。</translation>
    </message>
    <message>
        <source>The profile sets the normal mode.</source>
        <translation>参数文件设定为常规模式。</translation>
    </message>
    <message>
        <source>The profile sets special mode %1.</source>
        <translation>参数文件设定为特殊模式 %1。</translation>
    </message>
    <message>
        <source>Modes 2-5 ignore the limit settings: the limit and home inputs set for the motors no longer stop anything.</source>
        <translation>模式 2-5 忽略限位设置：为电机设置的限位和原点输入不再起作用。</translation>
    </message>
</context>
<context>
    <name>stepcom::MotionJudge</name>
    <message>
        <source>Motor %1&apos;s positive limit (IN%2) is already ON and %3 drives motor %1 forward: it stops at once.</source>
        <translation>电机 %1 的正限位（IN%2）已经接通，而%3会使电机 %1 正向运动：它会立即停止。</translation>
    </message>
    <message>
        <source>Motor %1&apos;s negative limit (IN%2) is already ON and %3 drives motor %1 in reverse: it stops at once.</source>
        <translation>电机 %1 的负限位（IN%2）已经接通，而%3会使电机 %1 反向运动：它会立即停止。</translation>
    </message>
    <message>
        <source>the single move</source>
        <translation>单次运动</translation>
    </message>
    <message>
        <source>the return to data zero</source>
        <translation>回数据零点</translation>
    </message>
    <message>
        <source>the approach to the start point</source>
        <translation>到起点的趋近运动</translation>
    </message>
    <message>
        <source>the arc</source>
        <translation>圆弧</translation>
    </message>
    <message>
        <source>the line</source>
        <translation>直线</translation>
    </message>
    <message>
        <source>Single move of motor %1</source>
        <translation>电机 %1 单次运动</translation>
    </message>
    <message>
        <source>Homing motor %1</source>
        <translation>电机 %1 回机械零</translation>
    </message>
    <message>
        <source>Homing in order</source>
        <translation>按顺序回机械零</translation>
    </message>
    <message>
        <source>Return to data zero</source>
        <translation>回数据零点</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>圆弧</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>直线</translation>
    </message>
    <message>
        <source>stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>E-STOP</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>link lost</source>
        <translation>连接丢失</translation>
    </message>
    <message>
        <source>an unknown position</source>
        <translation>未知位置</translation>
    </message>
    <message>
        <source>motor %1&apos;s positive limit (IN%2) is ON</source>
        <translation>电机 %1 的正限位（IN%2）接通</translation>
    </message>
    <message>
        <source>motor %1&apos;s negative limit (IN%2) is ON</source>
        <translation>电机 %1 的负限位（IN%2）接通</translation>
    </message>
    <message>
        <source>%1: done at %2</source>
        <translation>%1：已完成，位于 %2</translation>
    </message>
    <message>
        <source>%1: referenced at %2</source>
        <translation>%1：已建立参考点，位于 %2</translation>
    </message>
    <message>
        <source>no stop, limit or E-STOP seen</source>
        <translation>未见停止、限位或急停</translation>
    </message>
    <message>
        <source>%1: stopped at %2, not at the end point %3 (%4)</source>
        <translation>%1：停在 %2，未到终点 %3（%4）</translation>
    </message>
    <message>
        <source>%1 interrupted at %2 (%3): not referenced</source>
        <translation>%1 在 %2 处被中断（%3）：未建立参考点</translation>
    </message>
    <message>
        <source>%1 interrupted at %2 (%3): motor %4 not referenced</source>
        <translation>%1 在 %2 处被中断（%3）：电机 %4 未建立参考点</translation>
    </message>
    <message>
        <source>%1 ended without the home input at %2: not referenced</source>
        <translation>%1 结束于 %2，原点输入未接通：未建立参考点</translation>
    </message>
    <message>
        <source>%1 ended without the home input at %2: motor %3 not referenced</source>
        <translation>%1 结束于 %2，原点输入未接通：电机 %3 未建立参考点</translation>
    </message>
    <message>
        <source>the controller restarted</source>
        <translation>控制器重新启动了</translation>
    </message>
    <message>
        <source>no answer while it moved; the controller may have restarted</source>
        <translation>运动时没有应答；控制器可能重新启动了</translation>
    </message>
    <message>
        <source>%1: how it ended is not known, last seen at %2 (%3): not referenced</source>
        <translation>%1：不知道它是如何结束的，最后一次看到时位于 %2（%3）：未建立参考点</translation>
    </message>
</context>
<context>
    <name>stepcom::MotionPage</name>
    <message>
        <source>Coordinates zeroed</source>
        <translation>坐标已清零</translation>
    </message>
    <message>
        <source>Jog and home</source>
        <translation>点动与回零</translation>
    </message>
    <message>
        <source>%1…</source>
        <translation>%1…</translation>
    </message>
    <message>
        <source>%1… motor %2 running</source>
        <translation>%1… 电机 %2 运行中</translation>
    </message>
    <message>
        <source>&quot;Home in order&quot; uses the order the controller holds (%1) until you apply the edit.</source>
        <translation>在应用修改之前，“顺序回机械零”仍使用控制器中的回零顺序（%1）。</translation>
    </message>
    <message>
        <source>Homes %1.</source>
        <translation>回零顺序：%1。</translation>
    </message>
    <message>
        <source>&amp;Clear</source>
        <translation>清除(&amp;C)</translation>
    </message>
    <message>
        <source>Hide this note; the messages dock keeps it</source>
        <translation>隐藏此提示；“消息”窗口中仍会保留</translation>
    </message>
    <message>
        <source>&amp;Keyboard jogging</source>
        <translation>键盘点动(&amp;K)</translation>
    </message>
    <message>
        <source>Off by default. When on, the arrow keys jog while this page is shown and the window has focus</source>
        <translation>默认关闭。开启后，在显示此页面且窗口获得焦点时，可用方向键点动</translation>
    </message>
    <message>
        <source>⌨ KEYBOARD JOGGING ON</source>
        <translation>⌨ 键盘点动已开启</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>回零</translation>
    </message>
    <message>
        <source>Apply o&amp;rder</source>
        <translation>应用顺序(&amp;R)</translation>
    </message>
    <message>
        <source>Home &amp;in order</source>
        <translation>顺序回机械零(&amp;I)</translation>
    </message>
    <message>
        <source>&amp;Zero coordinates</source>
        <translation>坐标清零(&amp;Z)</translation>
    </message>
    <message>
        <source>Make the present positions of all motors 0; nothing moves</source>
        <translation>将所有电机的当前坐标设为 0；电机不运动</translation>
    </message>
    <message>
        <source>Re&amp;turn to data zero</source>
        <translation>回数据零(&amp;T)</translation>
    </message>
    <message>
        <source>Drive every idle motor back to position 0</source>
        <translation>让所有未运行的电机回到坐标 0</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>输出</translation>
    </message>
    <message>
        <source>Output 1 o&amp;n</source>
        <translation>第 1 路输出开(&amp;N)</translation>
    </message>
    <message>
        <source>O&amp;utput 1 off</source>
        <translation>第 1 路输出关(&amp;U)</translation>
    </message>
    <message>
        <source>All out&amp;puts on</source>
        <translation>输出全开(&amp;P)</translation>
    </message>
    <message>
        <source>All &amp;outputs off</source>
        <translation>输出全关(&amp;O)</translation>
    </message>
    <message>
        <source>Write just the homing order to the controller: the write dialog shows it first, then it is written and read back</source>
        <translation>只将回零顺序写入控制器：先在写入对话框中显示，然后写入并回读</translation>
    </message>
    <message>
        <source>Keys: ← → motor 1 reverse/forward, ↓ ↑ motor 2 reverse/forward, Home PgUp End PgDn the diagonals (both motors). Hold to move, let go to stop. Not while typing in a field; leaving the page or the window stops.</source>
        <translation>按键：← → 电机 1 反转/正转，↓ ↑ 电机 2 反转/正转，Home、PgUp、End、PgDn 斜向（两个电机同时）。按住运动，松开停止。在输入框中输入时无效；离开页面或窗口即停止。</translation>
    </message>
</context>
<context>
    <name>stepcom::MotorPage</name>
    <message>
        <source>Motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>Computed from the values shown, including edits not written yet.</source>
        <translation>根据当前显示的值计算，包括尚未写入的修改。</translation>
    </message>
    <message>
        <source>Computed from the values shown.</source>
        <translation>根据当前显示的值计算。</translation>
    </message>
    <message>
        <source>Motor %1 parameters</source>
        <translation>电机 %1 参数</translation>
    </message>
    <message>
        <source>Derived values</source>
        <translation>换算值</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>运行控制</translation>
    </message>
    <message>
        <source>&amp;Stop motor %1</source>
        <translation>停止电机 %1(&amp;S)</translation>
    </message>
    <message>
        <source>Stops the motor at once, without a ramp. The E-STOP under every page stops everything.</source>
        <translation>立即停止电机，不经减速。每个页面下方的“急停”会停止所有电机并关闭所有输出。</translation>
    </message>
</context>
<context>
    <name>stepcom::MoveHere</name>
    <message>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>a move is under way</source>
        <translation>有运动正在进行</translation>
    </message>
    <message>
        <source>motor %1 is not referenced: home it first</source>
        <translation>电机 %1 未建立参考点：请先回原点</translation>
    </message>
    <message>
        <source>the position of motor %1 is not known</source>
        <translation>电机 %1 的位置未知</translation>
    </message>
    <message>
        <source>Move here (%1, %2)</source>
        <translation>运行到此处 (%1, %2)</translation>
    </message>
    <message>
        <source>Move here: %1</source>
        <translation>运行到此处：%1</translation>
    </message>
    <message>
        <source>Not moved: %1.</source>
        <translation>未运动：%1。</translation>
    </message>
    <message>
        <source>motor %1: %2 → %3 %4 (%5%6 %4)</source>
        <translation>电机 %1：%2 → %3 %4（%5%6 %4）</translation>
    </message>
    <message>
        <source>Move both axes to (%1, %2)?
%3</source>
        <translation>让两个轴运行到 (%1, %2) 吗？
%3</translation>
    </message>
    <message>
        <source>Move here</source>
        <translation>运行到此处</translation>
    </message>
    <message>
        <source>Not moved.</source>
        <translation>未运动。</translation>
    </message>
    <message>
        <source>Not moved: %1</source>
        <translation>未运动：%1</translation>
    </message>
    <message>
        <source>Moving to (%1, %2)…</source>
        <translation>正在运行到 (%1, %2)…</translation>
    </message>
</context>
<context>
    <name>stepcom::OfflineActions</name>
    <message>
        <source>&amp;New profile from factory values</source>
        <translation>用出厂值新建参数文件(&amp;N)</translation>
    </message>
    <message>
        <source>Edit a new profile, starting from the factory values, without a controller</source>
        <translation>以出厂值为起点编辑一个新的参数文件，无需控制器</translation>
    </message>
    <message>
        <source>Save p&amp;rofile file</source>
        <translation>保存参数文件(&amp;R)</translation>
    </message>
    <message>
        <source>Save the profile being edited to its file (no controller is written)</source>
        <translation>把正在编辑的参数文件保存到其文件（不写入任何控制器）</translation>
    </message>
    <message>
        <source>Save profile file &amp;as…</source>
        <translation>参数文件另存为(&amp;A)…</translation>
    </message>
    <message>
        <source>Save the profile being edited to another file</source>
        <translation>把正在编辑的参数文件保存为另一个文件</translation>
    </message>
    <message>
        <source>&amp;Close profile file</source>
        <translation>关闭参数文件(&amp;C)</translation>
    </message>
    <message>
        <source>Stop editing the profile file</source>
        <translation>结束编辑参数文件</translation>
    </message>
    <message>
        <source>&amp;Compare profiles…</source>
        <translation>比较参数文件(&amp;C)…</translation>
    </message>
    <message>
        <source>Compare two profile files row by row; no controller is needed</source>
        <translation>逐行比较两个参数文件，无需控制器</translation>
    </message>
    <message>
        <source>Report from a &amp;profile…</source>
        <translation>根据参数文件生成报告(&amp;P)…</translation>
    </message>
    <message>
        <source>The commissioning report made from a profile file (or the file being edited), not from a controller</source>
        <translation>根据参数文件（或正在编辑的文件）生成调试报告，而不是读取控制器</translation>
    </message>
    <message>
        <source>Unsaved edits</source>
        <translation>未保存的修改</translation>
    </message>
    <message numerus="yes">
        <source>%n edited value(s) of %1 are not saved in the file.</source>
        <translation>
            <numerusform>%1 中有 %n 个修改过的值尚未保存到文件。</numerusform>
        </translation>
    </message>
    <message>
        <source>The profile cannot be edited</source>
        <translation>无法编辑此参数文件</translation>
    </message>
    <message>
        <source>Editing the profile file %1 without a controller</source>
        <translation>正在离线编辑参数文件 %1（未连接控制器）</translation>
    </message>
    <message>
        <source>New profile</source>
        <translation>新建参数文件</translation>
    </message>
    <message>
        <source>Editing a new profile with the factory values; nothing is written to a controller</source>
        <translation>正在编辑以出厂值新建的参数文件；不会向任何控制器写入</translation>
    </message>
    <message>
        <source>Save profile</source>
        <translation>保存参数文件</translation>
    </message>
    <message>
        <source>Saved the profile to %1 (no controller was written)</source>
        <translation>参数文件已保存到 %1（未写入任何控制器）</translation>
    </message>
    <message numerus="yes">
        <source>The file lacked %n setting(s); they were saved with their factory values: %1</source>
        <translation>
            <numerusform>文件缺少 %n 个设置，已用出厂值保存：%1</numerusform>
        </translation>
    </message>
    <message>
        <source>Save profile file as</source>
        <translation>参数文件另存为</translation>
    </message>
    <message>
        <source>StepCom profiles (*.json)</source>
        <translation>StepCom 参数文件 (*.json)</translation>
    </message>
    <message>
        <source>Compare profiles: choose two files</source>
        <translation>比较参数文件：选择两个文件</translation>
    </message>
    <message>
        <source>StepCom profiles (*.json);;All files (*)</source>
        <translation>StepCom 参数文件 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Compare profiles</source>
        <translation>比较参数文件</translation>
    </message>
    <message numerus="yes">
        <source>Choose exactly two profile files (%n chosen).</source>
        <translation>
            <numerusform>请正好选择两个参数文件（已选择 %n 个）。</numerusform>
        </translation>
    </message>
    <message>
        <source>The profiles cannot be compared</source>
        <translation>无法比较这两个参数文件</translation>
    </message>
    <message>
        <source>Compared %1 with %2</source>
        <translation>已比较 %1 与 %2</translation>
    </message>
    <message>
        <source>Report from a profile: choose the profile</source>
        <translation>根据参数文件生成报告：选择参数文件</translation>
    </message>
    <message>
        <source>Report from a profile</source>
        <translation>根据参数文件生成报告</translation>
    </message>
    <message>
        <source>Notes for the report (empty: the profile&apos;s own notes):</source>
        <translation>报告备注（留空则使用参数文件中的备注）：</translation>
    </message>
    <message>
        <source>Save the report made from the profile</source>
        <translation>保存根据参数文件生成的报告</translation>
    </message>
    <message>
        <source>PDF (*.pdf);;HTML (*.html)</source>
        <translation>PDF (*.pdf);;HTML (*.html)</translation>
    </message>
    <message>
        <source>Report made from the profile file %1 (no controller was read) written to %2</source>
        <translation>根据参数文件 %1 生成的报告（未读取控制器）已保存到 %2</translation>
    </message>
    <message>
        <source>(with edits not saved in the file)</source>
        <translation>（含尚未保存到文件的修改）</translation>
    </message>
    <message>
        <source>new profile</source>
        <translation>新参数文件</translation>
    </message>
    <message numerus="yes">
        <source>Profile applied: %n value(s) written and verified</source>
        <translation>
            <numerusform>已应用参数文件：写入并校验 %n 个值</numerusform>
        </translation>
    </message>
    <message>
        <source>Connected: the values of %1 are compared with the controller&apos;s; nothing is written until you apply checked rows</source>
        <translation>已连接：正在将 %1 中的值与控制器比较；应用勾选项之前不会写入任何数据</translation>
    </message>
    <message numerus="yes">
        <source>%n edit(s) of %1 were never saved: they are in the comparison, not in the file</source>
        <translation>
            <numerusform>%1 的 %n 处修改从未保存：它们在比较窗口中，不在文件中</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stepcom::OfflineBanner</name>
    <message>
        <source>Editing the profile file %1 — no controller. Nothing here moves or writes a controller; connect to compare the values with one and apply them.</source>
        <translation>正在编辑参数文件 %1 — 未连接控制器。这里的任何操作都不会让控制器运动或向控制器写入；连接后可与控制器比较并应用这些值。</translation>
    </message>
    <message>
        <source>Edits not saved yet.</source>
        <translation>修改尚未保存。</translation>
    </message>
    <message>
        <source>This map cannot take everything the file holds (saved again, the file keeps it; settings it lacks are filled with factory values when you save):</source>
        <translation>此寄存器表无法接受文件中的全部内容（再次保存时文件会保留这些内容；文件缺少的设置在保存时用出厂值补上）：</translation>
    </message>
</context>
<context>
    <name>stepcom::PageSidebar</name>
    <message numerus="yes">
        <source>%n edit(s) not written</source>
        <translation>
            <numerusform>%n 处修改未写入</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 of %2 steps passed</source>
        <translation>%2 步中已通过 %1 步</translation>
    </message>
    <message>
        <source>steps passed not known</source>
        <translation>已通过的步骤未知</translation>
    </message>
    <message>
        <source>needs a controller that answers (%1)</source>
        <translation>需要有应答的控制器（%1）</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>建立连接</translation>
    </message>
    <message>
        <source>Set up</source>
        <translation>设置</translation>
    </message>
    <message>
        <source>Move and run</source>
        <translation>运动与运行</translation>
    </message>
    <message>
        <source>Check, save and report</source>
        <translation>检查、保存与报告</translation>
    </message>
    <message>
        <source>More pages above</source>
        <translation>上方还有页面</translation>
    </message>
    <message>
        <source>More pages below</source>
        <translation>下方还有页面</translation>
    </message>
</context>
<context>
    <name>stepcom::Parameter</name>
    <message>
        <source>%1: %2 is not one of %3</source>
        <translation>%1：%2 不是 %3 之一</translation>
    </message>
    <message>
        <source>%1: %2 is out of range (%3)</source>
        <translation>%1：%2 超出范围（%3）</translation>
    </message>
    <message>
        <source>%1: no value given</source>
        <translation>%1：未给出数值</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1：“%2”不是数字</translation>
    </message>
    <message numerus="yes">
        <source>%1: &apos;%2&apos; has more than %n decimal(s)</source>
        <translation>
            <numerusform>%1：“%2”的小数超过 %n 位</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is far too large</source>
        <translation>%1：“%2”过大</translation>
    </message>
    <message>
        <source>%1: not a finite number</source>
        <translation>%1：不是有限数值</translation>
    </message>
    <message>
        <source>%1: %2 is far too large</source>
        <translation>%1：%2 过大</translation>
    </message>
    <message numerus="yes">
        <source>%1: %2 has more than %n decimal(s)</source>
        <translation>
            <numerusform>%1：%2 的小数超过 %n 位</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not one of %3</source>
        <translation>%1：“%2”不是 %3 之一</translation>
    </message>
</context>
<context>
    <name>stepcom::ParameterField</name>
    <message>
        <source>Not read from the controller yet</source>
        <translation>尚未从控制器读取</translation>
    </message>
    <message>
        <source>The controller holds this value</source>
        <translation>与控制器中的值一致</translation>
    </message>
    <message>
        <source>Edited, not written yet (the controller holds %1)</source>
        <translation>已修改，尚未写入（控制器中的值为 %1）</translation>
    </message>
    <message>
        <source>Edited, not written yet</source>
        <translation>已修改，尚未写入</translation>
    </message>
    <message>
        <source>Write failed: %1</source>
        <translation>写入失败：%1</translation>
    </message>
    <message>
        <source>The profile file lacks this value</source>
        <translation>参数文件中没有此值</translation>
    </message>
    <message>
        <source>The profile file holds this value</source>
        <translation>参数文件中的值</translation>
    </message>
    <message>
        <source>Edited, not saved yet (the file holds %1)</source>
        <translation>已修改，尚未保存（文件中为 %1）</translation>
    </message>
    <message>
        <source>Edited, not saved yet</source>
        <translation>已修改，尚未保存</translation>
    </message>
    <message>
        <source>Not supported by this controller: it refuses to read this register</source>
        <translation>此控制器不支持：控制器拒绝读取这个寄存器</translation>
    </message>
</context>
<context>
    <name>stepcom::ParameterStore</name>
    <message>
        <source>unknown parameter %1</source>
        <translation>未知参数 %1</translation>
    </message>
    <message>
        <source>%1 is read-only</source>
        <translation>%1 为只读参数</translation>
    </message>
    <message>
        <source>the controller holds %1 instead</source>
        <translation>控制器中的值实际为 %1</translation>
    </message>
    <message>
        <source>not written: an earlier write failed</source>
        <translation>未写入：之前的写入失败</translation>
    </message>
    <message>
        <source>%1 is not supported by this controller</source>
        <translation>此控制器不支持 %1</translation>
    </message>
</context>
<context>
    <name>stepcom::PathEditor</name>
    <message>
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 分 %2 秒</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>半径</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>圆心</translation>
    </message>
    <message>
        <source>Start / end radius</source>
        <translation>起点 / 终点半径</translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation>圆心角</translation>
    </message>
    <message>
        <source>Path length</source>
        <translation>路径长度</translation>
    </message>
    <message>
        <source>Path speed</source>
        <translation>路径速度</translation>
    </message>
    <message>
        <source>Estimated time</source>
        <translation>预计时间</translation>
    </message>
    <message>
        <source>Not connected.</source>
        <translation>未连接。</translation>
    </message>
    <message>
        <source>A value is being typed: press Enter to keep it, then write it.</source>
        <translation>正在输入数值：按回车确认，然后写入。</translation>
    </message>
    <message>
        <source>Changes not written yet: write them first, so the controller runs what the preview shows.</source>
        <translation>更改尚未写入：请先写入，使控制器运行的正是预览所示路径。</translation>
    </message>
    <message>
        <source>Not read from the controller yet.</source>
        <translation>尚未从控制器读取。</translation>
    </message>
    <message>
        <source>The geometry is invalid: %1</source>
        <translation>几何参数无效：%1</translation>
    </message>
    <message>
        <source>Arc interpolation is off (40182): choose “Motors 1+2 interpolate” and write it.</source>
        <translation>圆弧插补已关闭 (40182)：请选择“电机 1、2 插补”并写入。</translation>
    </message>
    <message>
        <source>Line interpolation is off (40202): choose “Motors 1+2 interpolate” and write it.</source>
        <translation>直线插补已关闭 (40202)：请选择“电机 1、2 插补”并写入。</translation>
    </message>
    <message>
        <source>A motor is moving: wait until it stops, or stop it.</source>
        <translation>有电机正在运行：请等待其停止，或将其停止。</translation>
    </message>
    <message>
        <source>Starting…</source>
        <translation>正在启动…</translation>
    </message>
    <message>
        <source> — computed from the three points</source>
        <translation> — 由三点计算得出</translation>
    </message>
    <message>
        <source>%1 / %2 (difference %3, at most %4)</source>
        <translation>%1 / %2（差值 %3，最大允许 %4）</translation>
    </message>
    <message>
        <source>%1° (full circle)</source>
        <translation>%1°（整圆）</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>%1 rpm = %2 %3/s</source>
        <translation>%1 rpm = %2 %3/s</translation>
    </message>
    <message>
        <source>%1 (approach %2 + path %3)</source>
        <translation>%1（趋近 %2 + 路径 %3）</translation>
    </message>
    <message>
        <source>Ready: Start runs the path shown, as written.</source>
        <translation>就绪：启动将按已写入的参数运行所示路径。</translation>
    </message>
    <message>
        <source>Arc parameters</source>
        <translation>圆弧参数</translation>
    </message>
    <message>
        <source>Line parameters</source>
        <translation>直线参数</translation>
    </message>
    <message>
        <source>What the controller will do</source>
        <translation>控制器将执行的运动</translation>
    </message>
    <message>
        <source>Run the arc</source>
        <translation>运行圆弧</translation>
    </message>
    <message>
        <source>Run the line</source>
        <translation>运行直线</translation>
    </message>
    <message>
        <source>Estimated time: the approach from where the axes are now (each axis on its own at its own speed) plus the path, driven at the set speed as motor 1 revolutions per minute with motor 1&apos;s start frequency, acceleration and pitch, as the simulator runs it. A real controller may differ.</source>
        <translation>预计时间：从当前位置的趋近移动（各轴以自身速度单独运行）加上路径运行；路径按设定速度（以电机 1 的转速计）并使用电机 1 的启动频率、加速度和螺距计算，与仿真器一致。实际控制器可能有所不同。</translation>
    </message>
    <message>
        <source>&amp;Write changes…</source>
        <translation>写入更改(&amp;W)…</translation>
    </message>
    <message>
        <source>Write this editor&apos;s changes to the controller and read them back</source>
        <translation>将本编辑器的更改写入控制器并回读校验</translation>
    </message>
    <message>
        <source>Start arc</source>
        <translation>启动圆弧</translation>
    </message>
    <message>
        <source>Start line</source>
        <translation>启动直线</translation>
    </message>
    <message>
        <source>Coil 00100: each axis first moves to the start point on its own, then both follow the arc</source>
        <translation>线圈 00100：各轴先单独运行到起点，然后两轴沿圆弧插补运行</translation>
    </message>
    <message>
        <source>Coil 00102: each axis first moves to the start point on its own, then both follow the line</source>
        <translation>线圈 00102：各轴先单独运行到起点，然后两轴沿直线插补运行</translation>
    </message>
    <message>
        <source>Stop arc</source>
        <translation>停止圆弧</translation>
    </message>
    <message>
        <source>Stop line</source>
        <translation>停止直线</translation>
    </message>
    <message>
        <source>Coil 00101, sent ahead of everything queued</source>
        <translation>线圈 00101，优先于所有排队请求发送</translation>
    </message>
    <message>
        <source>Coil 00103, sent ahead of everything queued</source>
        <translation>线圈 00103，优先于所有排队请求发送</translation>
    </message>
    <message>
        <source>⚠ Start is possible, but: %1</source>
        <translation>⚠ 可以启动，但是：%1</translation>
    </message>
    <message>
        <source>%1: running…</source>
        <translation>%1：运行中…</translation>
    </message>
    <message>
        <source>Last run: %1</source>
        <translation>上次运行：%1</translation>
    </message>
    <message>
        <source>Times as the simulator runs the path; a real controller may differ.</source>
        <translation>时间按模拟器运行路径估算；实际控制器可能不同。</translation>
    </message>
</context>
<context>
    <name>stepcom::PendantActions</name>
    <message>
        <source>A replay serves no pendant: close the session log first</source>
        <translation>回放时不提供手持器：请先关闭会话日志</translation>
    </message>
    <message>
        <source>A profile file edited without a controller serves no pendant</source>
        <translation>离线编辑参数文件时不提供手持器</translation>
    </message>
    <message>
        <source>A phone or tablet as the pendant: watch, E-STOP, and jog when you allow it</source>
        <translation>将手机或平板用作手持器：监视、急停，并在允许时点动</translation>
    </message>
    <message>
        <source>Pendant: jogging from %1</source>
        <translation>手持器：%1 正在点动</translation>
    </message>
    <message>
        <source>Pendant: on, no phone yet</source>
        <translation>手持器：已开启，尚无手机</translation>
    </message>
    <message>
        <source>Pendant: 1 phone watching</source>
        <translation>手持器：1 部手机在监视</translation>
    </message>
    <message>
        <source>Pendant: %1 phones watching</source>
        <translation>手持器：%1 部手机在监视</translation>
    </message>
    <message>
        <source>Pendant…</source>
        <translation>手持器…</translation>
    </message>
    <message>
        <source>Listening beside another master serves no pendant: stop listening first</source>
        <translation>在另一个主站旁监听时不提供手持器：请先停止监听</translation>
    </message>
</context>
<context>
    <name>stepcom::PendantControl</name>
    <message>
        <source>no hold from the pendant for %1 ms</source>
        <translation>%1 毫秒内未收到手持器的按住信号</translation>
    </message>
    <message>
        <source>the pendant stopped</source>
        <translation>手持器已停止</translation>
    </message>
    <message>
        <source>jogging from the pendant was turned off</source>
        <translation>已关闭从手持器点动</translation>
    </message>
    <message>
        <source>Jogging from the pendant is not allowed in the window</source>
        <translation>窗口中未允许从手持器点动</translation>
    </message>
    <message>
        <source>another phone took control</source>
        <translation>另一部手机取得了控制权</translation>
    </message>
    <message>
        <source>the phone gave up control</source>
        <translation>手机已交出控制权</translation>
    </message>
    <message>
        <source>the window took control back</source>
        <translation>窗口收回了控制权</translation>
    </message>
    <message>
        <source>the phone&apos;s connection closed</source>
        <translation>手机的连接已关闭</translation>
    </message>
    <message>
        <source>Take control first</source>
        <translation>请先取得控制权</translation>
    </message>
    <message>
        <source>Another phone holds control</source>
        <translation>另一部手机持有控制权</translation>
    </message>
    <message>
        <source>There is no motor %1</source>
        <translation>没有电机 %1</translation>
    </message>
    <message>
        <source>Motor %1 does not move</source>
        <translation>电机 %1 未运动</translation>
    </message>
    <message>
        <source>A step must be greater than 0</source>
        <translation>步距必须大于 0</translation>
    </message>
</context>
<context>
    <name>stepcom::PendantDialog</name>
    <message>
        <source>Pendant</source>
        <translation>手持器</translation>
    </message>
    <message>
        <source>A phone or tablet on the same network becomes the pendant: scan the code or type the address into its browser. It shows the positions, inputs and outputs and has an E-STOP; it jogs only while you allow it here.</source>
        <translation>同一网络中的手机或平板可作为手持器：扫描二维码，或在其浏览器中输入地址。它显示位置、输入和输出，并带有急停；只有在此处允许时才能点动。</translation>
    </message>
    <message>
        <source>&amp;Port:</source>
        <translation>端口(&amp;P)：</translation>
    </message>
    <message>
        <source>Allow jogging from the pendant</source>
        <translation>允许从手持器点动</translation>
    </message>
    <message>
        <source>Take control back</source>
        <translation>收回控制权</translation>
    </message>
    <message>
        <source>Phones connected:</source>
        <translation>已连接的手机：</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>地址</translation>
    </message>
    <message>
        <source>Browser</source>
        <translation>浏览器</translation>
    </message>
    <message>
        <source>Since</source>
        <translation>连接时间</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>断开(&amp;D)</translation>
    </message>
    <message>
        <source>The phone is no safety device: the machine&apos;s own E-STOP circuit stays the safety.</source>
        <translation>手机不是安全装置：机器自身的急停回路仍是安全保障。</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>QR code of the pendant&apos;s address</source>
        <translation>手持器地址的二维码</translation>
    </message>
    <message>
        <source>&amp;Stop the pendant</source>
        <translation>停止手持器(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Start the pendant</source>
        <translation>启动手持器(&amp;S)</translation>
    </message>
    <message>
        <source>The pendant is off.</source>
        <translation>手持器已关闭。</translation>
    </message>
    <message>
        <source>Pendant address: %1</source>
        <translation>手持器地址：%1</translation>
    </message>
    <message>
        <source>Control: %1</source>
        <translation>控制权：%1</translation>
    </message>
    <message>
        <source>Control: nobody (the window)</source>
        <translation>控制权：无人（窗口）</translation>
    </message>
</context>
<context>
    <name>stepcom::PendantPage</name>
    <message>
        <source>StepCom pendant</source>
        <translation>StepCom 手持器</translation>
    </message>
    <message>
        <source>Motor 1 position</source>
        <translation>电机 1 位置</translation>
    </message>
    <message>
        <source>Motor 2 position</source>
        <translation>电机 2 位置</translation>
    </message>
    <message>
        <source>Motor 1 forward</source>
        <translation>电机 1 正转</translation>
    </message>
    <message>
        <source>Motor 1 reverse</source>
        <translation>电机 1 反转</translation>
    </message>
    <message>
        <source>Motor 2 forward</source>
        <translation>电机 2 正转</translation>
    </message>
    <message>
        <source>Motor 2 reverse</source>
        <translation>电机 2 反转</translation>
    </message>
    <message>
        <source>Motor 1</source>
        <translation>电机 1</translation>
    </message>
    <message>
        <source>Motor 2</source>
        <translation>电机 2</translation>
    </message>
    <message>
        <source>E-STOP</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>Take control</source>
        <translation>取得控制权</translation>
    </message>
    <message>
        <source>Give up control</source>
        <translation>交出控制权</translation>
    </message>
    <message>
        <source>You hold control: hold a button to jog</source>
        <translation>您持有控制权：按住按钮即可点动</translation>
    </message>
    <message>
        <source>%1 holds control</source>
        <translation>%1 持有控制权</translation>
    </message>
    <message>
        <source>Watching only: jogging is not allowed in the window</source>
        <translation>仅监视：窗口中未允许点动</translation>
    </message>
    <message>
        <source>Jogging is allowed: take control to jog</source>
        <translation>已允许点动：取得控制权后即可点动</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>静止</translation>
    </message>
    <message>
        <source>running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <source>at a limit</source>
        <translation>在限位处</translation>
    </message>
    <message>
        <source>referenced</source>
        <translation>已回零</translation>
    </message>
    <message>
        <source>not referenced</source>
        <translation>未回零</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>输入</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>输出</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>port closed</source>
        <translation>端口已关闭</translation>
    </message>
    <message>
        <source>asking…</source>
        <translation>询问中…</translation>
    </message>
    <message>
        <source>not answering</source>
        <translation>无应答</translation>
    </message>
    <message>
        <source>answering</source>
        <translation>有应答</translation>
    </message>
    <message>
        <source>Device %1</source>
        <translation>设备 %1</translation>
    </message>
    <message>
        <source>%1 (id %2)</source>
        <translation>%1（ID %2）</translation>
    </message>
    <message>
        <source>no data</source>
        <translation>无数据</translation>
    </message>
    <message>
        <source>updated %1 s ago</source>
        <translation>%1 秒前更新</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>步距</translation>
    </message>
    <message>
        <source>Motor %1 step −</source>
        <translation>电机 %1 步进 −</translation>
    </message>
    <message>
        <source>Motor %1 step +</source>
        <translation>电机 %1 步进 +</translation>
    </message>
    <message>
        <source>The pendant was stopped in StepCom</source>
        <translation>手持器已在 StepCom 中停止</translation>
    </message>
    <message>
        <source>StepCom disconnected this phone</source>
        <translation>StepCom 已断开这部手机</translation>
    </message>
    <message>
        <source>Connection lost: reload the page</source>
        <translation>连接已断开：请重新加载页面</translation>
    </message>
    <message>
        <source>This phone is no safety device: the machine&apos;s own E-STOP is.</source>
        <translation>这部手机不是安全装置：机器自身的急停才是。</translation>
    </message>
</context>
<context>
    <name>stepcom::PendantServer</name>
    <message>
        <source>&apos;%1&apos; is not [ADDRESS:]PORT: the port must be a number from 0 to 65535</source>
        <translation>“%1”不是 [地址:]端口：端口必须是 0 到 65535 之间的数字</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not [ADDRESS:]PORT: &apos;%2&apos; is not an IP address</source>
        <translation>“%1”不是 [地址:]端口：“%2”不是 IP 地址</translation>
    </message>
    <message>
        <source>The pendant cannot listen on %1 port %2: %3</source>
        <translation>手持器无法在 %1 的端口 %2 上监听：%3</translation>
    </message>
</context>
<context>
    <name>stepcom::PlotPage</name>
    <message>
        <source>Plots</source>
        <translation>曲线图</translation>
    </message>
    <message>
        <source>Cannot write the picture “%1”.</source>
        <translation>无法写入图片“%1”。</translation>
    </message>
    <message>
        <source>Record status to CSV</source>
        <translation>将状态记录到 CSV</translation>
    </message>
    <message>
        <source>Export plots as PNG</source>
        <translation>将曲线图导出为 PNG</translation>
    </message>
    <message>
        <source>Export visible samples as CSV</source>
        <translation>将可见采样导出为 CSV</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG 图片 (*.png)</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Saved “%1”.</source>
        <translation>已保存“%1”。</translation>
    </message>
    <message numerus="yes">
        <source>Recording to “%1”: %n sample(s)</source>
        <translation>
            <numerusform>正在记录到“%1”：%n 个采样</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Not recording. Samples of the last %n minute(s) are kept for the plots and exports.</source>
        <translation>
            <numerusform>未在记录。曲线图和导出保留最近 %n 分钟的采样。</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Resume</source>
        <translation>继续(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>暂停(&amp;P)</translation>
    </message>
    <message>
        <source>Freeze the plots; samples are still taken and recorded</source>
        <translation>冻结曲线图；仍会继续采样和记录</translation>
    </message>
    <message>
        <source>&amp;Fit</source>
        <translation>全部显示(&amp;F)</translation>
    </message>
    <message>
        <source>Show all of the data (or double-click a plot). Drag to zoom into a region, wheel to zoom, middle button to pan.</source>
        <translation>显示全部数据（或双击曲线图）。拖动可放大某个区域，滚轮缩放，按住中键平移。</translation>
    </message>
    <message>
        <source>&amp;Clear path</source>
        <translation>清除轨迹(&amp;C)</translation>
    </message>
    <message>
        <source>Start the tool path trace again from here</source>
        <translation>从当前位置重新开始绘制运动轨迹</translation>
    </message>
    <message>
        <source>&amp;Window:</source>
        <translation>时间窗口(&amp;W)：</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>How many seconds the position plot shows</source>
        <translation>坐标曲线显示的时间长度（秒）</translation>
    </message>
    <message>
        <source>Export P&amp;NG…</source>
        <translation>导出 PNG(&amp;N)…</translation>
    </message>
    <message>
        <source>Save both plots as they are shown as a PNG picture</source>
        <translation>将两个曲线图按当前显示保存为 PNG 图片</translation>
    </message>
    <message>
        <source>Export CS&amp;V…</source>
        <translation>导出 CSV(&amp;V)…</translation>
    </message>
    <message>
        <source>Save the samples in the visible time range as CSV</source>
        <translation>将可见时间范围内的采样保存为 CSV</translation>
    </message>
    <message>
        <source>&amp;Stop recording</source>
        <translation>停止记录(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Record CSV…</source>
        <translation>记录 CSV(&amp;R)…</translation>
    </message>
    <message>
        <source>Write every status sample to a CSV file as it arrives</source>
        <translation>将收到的每个状态采样实时写入 CSV 文件</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>Motor %1 (%2)</source>
        <translation>电机 %1（%2）</translation>
    </message>
    <message>
        <source>Tool path</source>
        <translation>运动轨迹</translation>
    </message>
</context>
<context>
    <name>stepcom::Poller</name>
    <message numerus="yes">
        <source>… %n in all</source>
        <translation>
            <numerusform>… 共 %n 个</numerusform>
        </translation>
    </message>
    <message>
        <source>poll %1/%2 (%3)</source>
        <translation>轮询 %1/%2（%3）</translation>
    </message>
</context>
<context>
    <name>stepcom::PortHolders</name>
    <message>
        <source>process %1</source>
        <translation>进程 %1</translation>
    </message>
    <message>
        <source>%1, process %2</source>
        <translation>%1，进程 %2</translation>
    </message>
    <message>
        <source>%1 is in use by another program</source>
        <translation>%1 正被另一个程序占用</translation>
    </message>
    <message>
        <source>%1 is in use by another program (%2)</source>
        <translation>%1 正被另一个程序占用（%2）</translation>
    </message>
</context>
<context>
    <name>stepcom::PortSetup</name>
    <message>
        <source>its driver</source>
        <translation>其驱动</translation>
    </message>
    <message>
        <source>not on this system</source>
        <translation>本系统不支持</translation>
    </message>
    <message>
        <source>%1: the driver (%2) refused to switch RTS (%3); StepCom cannot drive the RS-485 direction by RTS here: try --rs485 auto with an adapter that switches by itself</source>
        <translation>%1：驱动（%2）拒绝切换 RTS（%3）；StepCom 无法在此用 RTS 控制 RS-485 方向：请改用 --rs485 auto，并使用能自动切换方向的适配器</translation>
    </message>
    <message>
        <source>%1: the driver (%2) has no kernel RS-485 mode (%3): try --rs485 rts (StepCom switches RTS itself) or --rs485 auto (the adapter switches by itself)</source>
        <translation>%1：驱动（%2）没有内核 RS-485 模式（%3）：请尝试 --rs485 rts（由 StepCom 自己切换 RTS）或 --rs485 auto（由适配器自动切换）</translation>
    </message>
    <message>
        <source>%1: RS-485 direction modes need Linux: use --rs485 auto</source>
        <translation>%1：RS-485 方向模式需要 Linux：请使用 --rs485 auto</translation>
    </message>
</context>
<context>
    <name>stepcom::PortSurvey</name>
    <message>
        <source>lock file %1</source>
        <translation>锁文件 %1</translation>
    </message>
    <message>
        <source>has it open</source>
        <translation>已打开它</translation>
    </message>
    <message>
        <source>whether another program holds it is not known here</source>
        <translation>此处无法得知是否被其他程序占用</translation>
    </message>
    <message>
        <source>free, as far as this user can see</source>
        <translation>空闲（就当前用户所能看到的而言）</translation>
    </message>
    <message>
        <source>free</source>
        <translation>空闲</translation>
    </message>
    <message>
        <source>%1 (pid %2, %3)</source>
        <translation>%1（pid %2，%3）</translation>
    </message>
    <message>
        <source>a program</source>
        <translation>某个程序</translation>
    </message>
    <message>
        <source>held by %1</source>
        <translation>被占用：%1</translation>
    </message>
</context>
<context>
    <name>stepcom::PositionPlot</name>
    <message>
        <source>Cannot write the picture “%1”.</source>
        <translation>无法写入图片“%1”。</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>坐标</translation>
    </message>
    <message>
        <source>Position (%1)</source>
        <translation>坐标（%1）</translation>
    </message>
    <message>
        <source>Drag to zoom into a region, wheel or +/- to zoom, middle button or arrow keys to pan, double-click or Home to fit. Zooming pauses the view.</source>
        <translation>拖动可放大某个区域，滚轮或 +/- 缩放，中键或方向键平移，双击或按 Home 键全部显示。缩放时视图暂停刷新。</translation>
    </message>
    <message>
        <source>Time (s), 0 = %1</source>
        <translation>时间（s），0 = %1</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileActions</name>
    <message>
        <source>&amp;Open profile…</source>
        <translation>打开参数文件(&amp;O)…</translation>
    </message>
    <message>
        <source>Compare a profile file with the controller; nothing is written until you apply checked rows</source>
        <translation>将参数文件与控制器比较；在应用勾选的行之前不会写入任何内容</translation>
    </message>
    <message>
        <source>Save profile from &amp;device…</source>
        <translation>从设备保存参数文件(&amp;D)…</translation>
    </message>
    <message>
        <source>Read every parameter, then save them as a profile file</source>
        <translation>读取全部参数，然后保存为参数文件</translation>
    </message>
    <message>
        <source>Save profile from &amp;edited values…</source>
        <translation>从编辑值保存参数文件(&amp;E)…</translation>
    </message>
    <message>
        <source>Save the values the pages show (edits included) as a profile file</source>
        <translation>将页面上显示的值（包括未写入的编辑）保存为参数文件</translation>
    </message>
    <message>
        <source>Commissioning &amp;report…</source>
        <translation>调试报告(&amp;R)…</translation>
    </message>
    <message>
        <source>Read everything, then write the commissioning sheet as PDF or HTML</source>
        <translation>读取全部数据，然后将调试报告保存为 PDF 或 HTML</translation>
    </message>
    <message>
        <source>Recent &amp;profiles</source>
        <translation>最近的参数文件(&amp;P)</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <source>Nothing was written to the controller.</source>
        <translation>未向控制器写入任何内容。</translation>
    </message>
    <message>
        <source>Open profile</source>
        <translation>打开参数文件</translation>
    </message>
    <message>
        <source>StepCom profiles (*.json);;All files (*)</source>
        <translation>StepCom 参数文件 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Save profile from the device</source>
        <translation>从设备保存参数文件</translation>
    </message>
    <message>
        <source>Save profile from the edited values</source>
        <translation>从编辑值保存参数文件</translation>
    </message>
    <message>
        <source>StepCom profiles (*.json)</source>
        <translation>StepCom 参数文件 (*.json)</translation>
    </message>
    <message>
        <source>Commissioning report</source>
        <translation>调试报告</translation>
    </message>
    <message>
        <source>Notes for the report (machine, place, who commissioned it):</source>
        <translation>报告备注（机器、地点、调试人员）：</translation>
    </message>
    <message>
        <source>Save the commissioning report</source>
        <translation>保存调试报告</translation>
    </message>
    <message>
        <source>PDF (*.pdf);;HTML (*.html)</source>
        <translation>PDF (*.pdf);;HTML (*.html)</translation>
    </message>
    <message>
        <source>The profile cannot be used</source>
        <translation>无法使用该参数文件</translation>
    </message>
    <message numerus="yes">
        <source>Profile applied: %n value(s) written and verified</source>
        <translation>
            <numerusform>已应用参数文件：写入并校验 %n 个值</numerusform>
        </translation>
    </message>
    <message>
        <source>Opened profile %1</source>
        <translation>已打开参数文件 %1</translation>
    </message>
    <message>
        <source>Save profile</source>
        <translation>保存参数文件</translation>
    </message>
    <message>
        <source>Connect to a controller first.</source>
        <translation>请先连接控制器。</translation>
    </message>
    <message>
        <source>Nothing was saved: the controller could not be read completely.</source>
        <translation>未保存任何内容：无法完整读取控制器。</translation>
    </message>
    <message numerus="yes">
        <source>Saved the controller&apos;s %n parameter(s) to %1</source>
        <translation>
            <numerusform>已将控制器的 %n 个参数保存到 %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) are not known yet (read all first): %1</source>
        <translation>
            <numerusform>%n 个值尚未知（请先全部读取）：%1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Saved %n value(s) as shown (edits included) to %1</source>
        <translation>
            <numerusform>已将显示的 %n 个值（包括编辑）保存到 %1</numerusform>
        </translation>
    </message>
    <message>
        <source>No report: the controller could not be read completely.</source>
        <translation>未生成报告：无法完整读取控制器。</translation>
    </message>
    <message>
        <source>Commissioning report written to %1</source>
        <translation>调试报告已写入 %1</translation>
    </message>
    <message>
        <source>Connected: compare a profile file with the controller (nothing is written until you apply checked rows). Without a controller: edit the file on the pages</source>
        <translation>已连接时：将参数文件与控制器比较（应用勾选项之前不写入任何数据）。未连接控制器时：在各页面上编辑该文件</translation>
    </message>
    <message>
        <source>The backup cannot be used</source>
        <translation>此备份无法使用</translation>
    </message>
    <message>
        <source>Opened backup %1</source>
        <translation>已打开备份 %1</translation>
    </message>
    <message>
        <source>&amp;Backups…</source>
        <translation>备份(&amp;B)…</translation>
    </message>
    <message>
        <source>The controller&apos;s settings saved before each apply, factory reset, save to flash and id or baud change</source>
        <translation>每次应用参数文件、恢复出厂参数、保存到闪存以及修改设备地址或波特率之前保存的控制器参数</translation>
    </message>
    <message>
        <source>The software travel limits of %1 are in use now</source>
        <translation>现在使用 %1 的软件行程限位</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileApply</name>
    <message>
        <source>not done: E-STOP</source>
        <translation>未执行：急停</translation>
    </message>
    <message>
        <source>stopped by the E-STOP: nothing more was sent for this profile</source>
        <translation>被急停中止：此配置不再发送任何内容</translation>
    </message>
    <message>
        <source>the link was closed</source>
        <translation>连接已关闭</translation>
    </message>
    <message>
        <source>the controller could not be read</source>
        <translation>无法读取控制器</translation>
    </message>
    <message>
        <source>the link was lost</source>
        <translation>连接已断开</translation>
    </message>
    <message>
        <source>the controller could not be read: %1</source>
        <translation>无法读取控制器：%1</translation>
    </message>
    <message>
        <source>the profile holds no value</source>
        <translation>配置中没有该值</translation>
    </message>
    <message>
        <source>this controller does not have it</source>
        <translation>此控制器没有该参数</translation>
    </message>
    <message>
        <source>the device id and baud are applied only to the device in view, when asked for</source>
        <translation>设备地址和波特率只在要求时应用于当前显示的设备</translation>
    </message>
    <message>
        <source>it is read-only</source>
        <translation>该参数只读</translation>
    </message>
    <message>
        <source>not a setting of this register map</source>
        <translation>不是此寄存器表中的参数</translation>
    </message>
    <message>
        <source>the session ended</source>
        <translation>会话已结束</translation>
    </message>
    <message>
        <source>the link was lost before it was sent</source>
        <translation>发送前连接已断开</translation>
    </message>
    <message>
        <source>stopped by the E-STOP while writing</source>
        <translation>写入时被急停中止</translation>
    </message>
    <message>
        <source>refused by the controller</source>
        <translation>被控制器拒绝</translation>
    </message>
    <message>
        <source>not sent: an earlier write failed</source>
        <translation>未发送：之前的写入失败</translation>
    </message>
    <message>
        <source>sent without a good answer</source>
        <translation>已发送，但没有收到正确应答</translation>
    </message>
    <message>
        <source>the controller restarted during the apply: what it held then was lost unless saved to flash</source>
        <translation>应用期间控制器重启：未保存到闪存的值已丢失</translation>
    </message>
    <message>
        <source>the controller restarted</source>
        <translation>控制器已重启</translation>
    </message>
    <message>
        <source>the controller holds %1</source>
        <translation>控制器保存的是 %1</translation>
    </message>
    <message>
        <source>this map has no save_to_flash command</source>
        <translation>此寄存器表没有 save_to_flash 命令</translation>
    </message>
    <message>
        <source>saved to flash only on the device in view</source>
        <translation>只能对当前显示的设备保存到闪存</translation>
    </message>
    <message>
        <source>the link went away during the apply (%1)</source>
        <translation>应用期间连接断开（%1）</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileApplyResult</name>
    <message>
        <source>%1: already %2</source>
        <translation>%1：已是 %2</translation>
    </message>
    <message>
        <source>%1: %2 (written, verified)</source>
        <translation>%1：%2（已写入，已校验）</translation>
    </message>
    <message>
        <source>%1: wrote %2, the controller holds %3</source>
        <translation>%1：写入 %2，控制器保存的是 %3</translation>
    </message>
    <message>
        <source>%1: wrote %2, could not read it back</source>
        <translation>%1：写入 %2，无法回读</translation>
    </message>
    <message>
        <source>%1: %2 refused: %3</source>
        <translation>%1：%2 被拒绝：%3</translation>
    </message>
    <message>
        <source>%1: not written (%2)</source>
        <translation>%1：未写入（%2）</translation>
    </message>
    <message>
        <source>%1: not known whether %2 was written (%3)</source>
        <translation>%1：不知道 %2 是否已写入（%3）</translation>
    </message>
    <message>
        <source>%1: wrote %2, then the controller held %3 again (%4)</source>
        <translation>%1：已写入 %2，之后控制器又变回 %3（%4）</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileCompareDialog</name>
    <message>
        <source>Saved to flash: the controller keeps these values after power-off.</source>
        <translation>已保存到闪存：控制器断电后仍保留这些值。</translation>
    </message>
    <message>
        <source>Saving to flash failed (see Messages).</source>
        <translation>保存到闪存失败（见“消息”）。</translation>
    </message>
    <message>
        <source>The controller forgets these values at power-off unless they are saved to flash.</source>
        <translation>除非保存到闪存，否则控制器断电后会丢失这些值。</translation>
    </message>
    <message>
        <source>Motor %1 · %2</source>
        <translation>电机 %1 · %2</translation>
    </message>
    <message>
        <source>link setting</source>
        <translation>通信设置</translation>
    </message>
    <message>
        <source>The profile does not hold this value</source>
        <translation>参数文件中没有该值</translation>
    </message>
    <message>
        <source>The controller&apos;s values are not known yet: connect, and they are read.</source>
        <translation>尚不知道控制器中的值：连接后会读取。</translation>
    </message>
    <message>
        <source>The controller holds every value of the profile.</source>
        <translation>控制器中的值与参数文件完全一致。</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) differ; %1 checked to be written.</source>
        <translation>
            <numerusform>%n 个值不同；已勾选 %1 个待写入。</numerusform>
        </translation>
    </message>
    <message>
        <source>Connect to a controller to apply</source>
        <translation>连接控制器后才能应用</translation>
    </message>
    <message numerus="yes">
        <source>Writing %n value(s), then reading them back…</source>
        <translation>
            <numerusform>正在写入 %n 个值，然后回读……</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Wrote and verified %n value(s).</source>
        <translation>
            <numerusform>已写入并校验 %n 个值。</numerusform>
        </translation>
    </message>
    <message>
        <source>Problems:</source>
        <translation>问题：</translation>
    </message>
    <message>
        <source>Profile %1 — compare and apply</source>
        <translation>参数文件 %1 — 比较与应用</translation>
    </message>
    <message>
        <source>Profile &quot;%1&quot; from %2</source>
        <translation>参数文件 &quot;%1&quot;，来自 %2</translation>
    </message>
    <message>
        <source>saved %1</source>
        <translation>保存于 %1</translation>
    </message>
    <message>
        <source>from controller id %1</source>
        <translation>来自设备地址 %1 的控制器</translation>
    </message>
    <message>
        <source>Opening a profile writes nothing. Check the rows to write, then Apply.</source>
        <translation>打开参数文件不会写入任何内容。勾选要写入的行，然后点击应用。</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <source>Profile</source>
        <translation>参数文件</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>键名</translation>
    </message>
    <message>
        <source>Differences only</source>
        <translation>只显示不同项</translation>
    </message>
    <message>
        <source>Also apply the device id and baud (the connection follows)</source>
        <translation>同时应用设备地址和波特率（连接随之切换）</translation>
    </message>
    <message>
        <source>Check differing</source>
        <translation>勾选不同项</translation>
    </message>
    <message>
        <source>Check none</source>
        <translation>全部取消勾选</translation>
    </message>
    <message>
        <source>Apply checked</source>
        <translation>应用勾选项</translation>
    </message>
    <message>
        <source>Save to flash</source>
        <translation>保存到闪存</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Not applied:</source>
        <translation>不应用：</translation>
    </message>
    <message>
        <source>Left out, not supported by this controller: %1.</source>
        <translation>已排除，此控制器不支持：%1。</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) the controller already held.</source>
        <translation>
            <numerusform>控制器已保存其中 %n 个值。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileDiff</name>
    <message>
        <source>%1: the profile holds no value</source>
        <translation>%1：参数文件中没有该值</translation>
    </message>
    <message>
        <source>(unknown)</source>
        <translation>（未知）</translation>
    </message>
    <message>
        <source>(not in the profile)</source>
        <translation>（参数文件中没有）</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileDocument</name>
    <message>
        <source>new profile</source>
        <translation>新参数文件</translation>
    </message>
    <message>
        <source>a controller is connected: open the profile to compare it instead</source>
        <translation>已连接控制器：请打开参数文件进行比较</translation>
    </message>
    <message>
        <source>a controller is connected: disconnect to edit a profile without it</source>
        <translation>已连接控制器：断开连接后才能离线编辑参数文件</translation>
    </message>
    <message>
        <source>Factory values</source>
        <translation>出厂值</translation>
    </message>
    <message>
        <source>no profile is being edited</source>
        <translation>没有正在编辑的参数文件</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileFile</name>
    <message>
        <source>null</source>
        <translation>null（空值）</translation>
    </message>
    <message>
        <source>true/false</source>
        <translation>true/false（布尔值）</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>一个数字</translation>
    </message>
    <message>
        <source>a text &quot;%1&quot;</source>
        <translation>文本 &quot;%1&quot;</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>一个列表</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>一个对象</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>无</translation>
    </message>
    <message>
        <source>the key &quot;%1&quot; appears more than once</source>
        <translation>键 &quot;%1&quot; 出现了不止一次</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the key &quot;%2&quot; appears more than once</source>
        <translation>&quot;%1&quot;：键 &quot;%2&quot; 出现了不止一次</translation>
    </message>
    <message>
        <source>the file is empty</source>
        <translation>文件为空</translation>
    </message>
    <message>
        <source>the file is %1 bytes: far too large for a profile</source>
        <translation>文件有 %1 字节：作为参数文件太大了</translation>
    </message>
    <message>
        <source>not valid JSON at line %1, column %2: %3</source>
        <translation>第 %1 行第 %2 列不是有效的 JSON：%3</translation>
    </message>
    <message>
        <source>the file holds a JSON list, not a profile object</source>
        <translation>文件内容是 JSON 列表，而不是参数文件对象</translation>
    </message>
    <message>
        <source>… and %1 more problems</source>
        <translation>…… 以及另外 %1 个问题</translation>
    </message>
    <message>
        <source>unknown field &quot;%1&quot; (allowed: %2)</source>
        <translation>未知字段 &quot;%1&quot;（允许：%2）</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: unknown field &quot;%2&quot; (allowed: %3)</source>
        <translation>&quot;%1&quot;：未知字段 &quot;%2&quot;（允许：%3）</translation>
    </message>
    <message>
        <source>this is a register map, not a profile</source>
        <translation>这是寄存器表文件，不是参数文件</translation>
    </message>
    <message>
        <source>not a StepCom profile: &quot;format&quot; must be &quot;%1&quot;, found %2</source>
        <translation>不是 StepCom 参数文件：&quot;format&quot; 应为 &quot;%1&quot;，实际为 %2</translation>
    </message>
    <message>
        <source>&quot;schema&quot; must be a whole number, found %1</source>
        <translation>&quot;schema&quot; 应为整数，实际为 %1</translation>
    </message>
    <message>
        <source>profile schema %1 is newer than this StepCom reads (%2): update StepCom</source>
        <translation>参数文件格式版本 %1 比本 StepCom 支持的版本（%2）新：请更新 StepCom</translation>
    </message>
    <message>
        <source>profile schema %1 is unknown (this StepCom reads %2)</source>
        <translation>未知的参数文件格式版本 %1（本 StepCom 支持 %2）</translation>
    </message>
    <message>
        <source>&quot;map&quot; must be an object {&quot;id&quot;: …, &quot;version&quot;: …}, found %1</source>
        <translation>&quot;map&quot; 应为对象 {&quot;id&quot;: …, &quot;version&quot;: …}，实际为 %1</translation>
    </message>
    <message>
        <source>&quot;map&quot;: &quot;id&quot; must be a text, found %1</source>
        <translation>&quot;map&quot;：&quot;id&quot; 应为文本，实际为 %1</translation>
    </message>
    <message>
        <source>&quot;map&quot;: &quot;version&quot; must be a whole number, found %1</source>
        <translation>&quot;map&quot;：&quot;version&quot; 应为整数，实际为 %1</translation>
    </message>
    <message>
        <source>the profile is for register map &quot;%1&quot; version %2, but the controller&apos;s map is &quot;%3&quot; version %4</source>
        <translation>该参数文件属于寄存器表 &quot;%1&quot; 版本 %2，但控制器的寄存器表是 &quot;%3&quot; 版本 %4</translation>
    </message>
    <message>
        <source>&quot;metadata&quot; must be an object, found %1</source>
        <translation>&quot;metadata&quot; 应为对象，实际为 %1</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;%1&quot; must be a text, found %2</source>
        <translation>&quot;metadata&quot;：&quot;%1&quot; 应为文本，实际为 %2</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;created&quot; is not a date and time (2024-05-31T14:02:00Z): &quot;%1&quot;</source>
        <translation>&quot;metadata&quot;：&quot;created&quot; 不是日期时间（2024-05-31T14:02:00Z）：&quot;%1&quot;</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;%1&quot; must be a %2, found %3</source>
        <translation>&quot;metadata&quot;：&quot;%1&quot; 应为 %2，实际为 %3</translation>
    </message>
    <message>
        <source>whole number</source>
        <translation>整数</translation>
    </message>
    <message>
        <source>&quot;values&quot; must be an object of key: value, found %1</source>
        <translation>&quot;values&quot; 应为 键: 值 形式的对象，实际为 %1</translation>
    </message>
    <message>
        <source>unknown parameter &quot;%1&quot; (not in register map &quot;%2&quot;)</source>
        <translation>未知参数 &quot;%1&quot;（不在寄存器表 &quot;%2&quot; 中）</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is a command, not a setting</source>
        <translation>&quot;%1&quot; 是命令，不是设置参数</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is read-only (a status value), not a setting</source>
        <translation>&quot;%1&quot; 是只读的状态值，不是设置参数</translation>
    </message>
    <message>
        <source>%1: expected a number, found %2</source>
        <translation>%1：应为数字，实际为 %2</translation>
    </message>
    <message>
        <source>missing &quot;%1&quot; (%2)</source>
        <translation>缺少 &quot;%1&quot;（%2）</translation>
    </message>
    <message>
        <source>no register map to check the profile against</source>
        <translation>没有可用于检查参数文件的寄存器表</translation>
    </message>
    <message>
        <source>%1: no such file</source>
        <translation>%1：文件不存在</translation>
    </message>
    <message>
        <source>%1: %2 bytes, far too large for a profile</source>
        <translation>%1：%2 字节，作为参数文件太大了</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>not in register map &quot;%1&quot;</source>
        <translation>不在寄存器表 &quot;%1&quot; 中</translation>
    </message>
    <message>
        <source>a command in register map &quot;%1&quot;, not a setting</source>
        <translation>在寄存器表 &quot;%1&quot; 中是命令，不是设置参数</translation>
    </message>
    <message>
        <source>a status value in register map &quot;%1&quot;, not a setting</source>
        <translation>在寄存器表 &quot;%1&quot; 中是状态值，不是设置参数</translation>
    </message>
    <message>
        <source>&quot;stepcom&quot; must be an object, found %1</source>
        <translation>“stepcom”必须是对象，实际为%1</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;backup&quot; must be {&quot;operation&quot;: one of %1, &quot;device&quot;: text}</source>
        <translation>“metadata”：“backup”必须是 {&quot;operation&quot;: %1 之一, &quot;device&quot;: 文本}</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;backup&quot;: &quot;device&quot; must be a text of at most 200 characters</source>
        <translation>“metadata”：“backup”：“device”必须是最多 200 个字符的文本</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;unsupported&quot; must be a list of keys, found %1</source>
        <translation>&quot;metadata&quot;：&quot;unsupported&quot; 必须是键名列表，实际为 %1</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;unsupported&quot;: %1 is no parameter of the map</source>
        <translation>&quot;metadata&quot;：&quot;unsupported&quot;：%1 不是寄存器表中的参数</translation>
    </message>
    <message>
        <source>&quot;metadata&quot;: &quot;source&quot; is &quot;simulator&quot; or absent, found &quot;%1&quot;</source>
        <translation>&quot;metadata&quot;：&quot;source&quot; 应为 &quot;simulator&quot; 或不写，实际为 &quot;%1&quot;</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileFilesDialog</name>
    <message>
        <source>differ</source>
        <translation>不同</translation>
    </message>
    <message>
        <source>the same</source>
        <translation>相同</translation>
    </message>
    <message>
        <source>only in A</source>
        <translation>只在 A 中</translation>
    </message>
    <message>
        <source>only in B</source>
        <translation>只在 B 中</translation>
    </message>
    <message>
        <source>outside this map</source>
        <translation>超出此寄存器表</translation>
    </message>
    <message>
        <source>Motor %1 · %2</source>
        <translation>电机 %1 · %2</translation>
    </message>
    <message>
        <source>(not a setting of this map)</source>
        <translation>（不是此寄存器表的设置）</translation>
    </message>
    <message>
        <source>%1 differ, %2 only in A, %3 only in B, %4 outside this map (%5 of them differ).</source>
        <translation>%1 项不同，%2 项只在 A 中，%3 项只在 B 中，%4 项超出此寄存器表（其中 %5 项不同）。</translation>
    </message>
    <message>
        <source>The files hold the same values.</source>
        <translation>两个文件的值相同。</translation>
    </message>
    <message>
        <source>The files differ.</source>
        <translation>两个文件不同。</translation>
    </message>
    <message>
        <source>Compare profiles: %1 and %2</source>
        <translation>比较参数文件：%1 与 %2</translation>
    </message>
    <message>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <source>register map %1</source>
        <translation>寄存器表 %1</translation>
    </message>
    <message>
        <source>Two files compared against register map %1/%2; no controller is read or written.</source>
        <translation>两个文件按寄存器表 %1/%2 比较；不读取也不写入任何控制器。</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>分组</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>参数名</translation>
    </message>
    <message>
        <source>Differences only</source>
        <translation>只显示不同项</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileRollout</name>
    <message>
        <source>could not be read: %1</source>
        <translation>无法读取：%1</translation>
    </message>
    <message>
        <source>it already holds the profile&apos;s values</source>
        <translation>设备已与参数文件一致</translation>
    </message>
    <message>
        <source>no value was chosen for it</source>
        <translation>没有为它勾选任何值</translation>
    </message>
    <message>
        <source>not every value could be verified</source>
        <translation>并非所有值都已校验</translation>
    </message>
    <message>
        <source>not done: E-STOP</source>
        <translation>未执行：急停</translation>
    </message>
    <message>
        <source>id %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>id %1 (%2)</source>
        <translation>ID %1（%2）</translation>
    </message>
    <message>
        <source>%1: waiting</source>
        <translation>%1：等待中</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n value(s) differ</source>
        <translation>
            <numerusform>%1：%n 个值不同</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: written and verified, %n value(s)</source>
        <translation>
            <numerusform>%1：已写入并校验，%n 个值</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: skipped, %2</source>
        <translation>%1：已跳过，%2</translation>
    </message>
    <message>
        <source>%1: FAILED, %2</source>
        <translation>%1：失败，%2</translation>
    </message>
    <message numerus="yes">
        <source>%1: FAILED, %2 (%n value(s) verified)</source>
        <translation>
            <numerusform>%1：失败，%2（%n 个值已校验）</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileSaveDialog</name>
    <message>
        <source>Controller id %1</source>
        <translation>控制器 ID %1</translation>
    </message>
    <message>
        <source>Profile</source>
        <translation>参数文件</translation>
    </message>
    <message>
        <source>Save profile</source>
        <translation>保存参数文件</translation>
    </message>
    <message>
        <source>Every parameter is read from the controller, then saved with this name and notes.</source>
        <translation>先从控制器读取全部参数，再以此名称和备注保存。</translation>
    </message>
    <message>
        <source>The values the pages show (edits included) are saved with this name and notes.</source>
        <translation>以此名称和备注保存页面上显示的值（包括修改值）。</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>名称(&amp;N)：</translation>
    </message>
    <message>
        <source>N&amp;otes:</source>
        <translation>备注(&amp;O)：</translation>
    </message>
    <message>
        <source>Machine, place, who set it up, what was changed</source>
        <translation>设备、地点、调试人、修改了什么</translation>
    </message>
</context>
<context>
    <name>stepcom::ProfileVariance</name>
    <message>
        <source>the profile was made with register map &quot;%1&quot;; this map is &quot;%2&quot;: only the settings both have can be applied</source>
        <translation>参数文件由寄存器表 &quot;%1&quot; 生成；当前寄存器表是 &quot;%2&quot;：只能应用两者共有的设置参数</translation>
    </message>
    <message>
        <source>unknown to this map: %1 = %2 (%3)</source>
        <translation>此寄存器表中没有：%1 = %2（%3）</translation>
    </message>
    <message>
        <source>cannot be applied: %1</source>
        <translation>无法应用：%1</translation>
    </message>
    <message>
        <source>not in the profile: %1 (%2)</source>
        <translation>参数文件中没有：%1（%2）</translation>
    </message>
</context>
<context>
    <name>stepcom::ProofDrive</name>
    <message>
        <source>There is no motor %1 (this controller has %2)</source>
        <translation>没有电机 %1（此控制器有 %2 个）</translation>
    </message>
    <message>
        <source>This register map has no %1 for motor %2: the axis cannot be proven</source>
        <translation>此寄存器表中电机 %2 没有 %1：无法验证该轴</translation>
    </message>
    <message>
        <source>Not connected: nothing was sent</source>
        <translation>未连接：没有发送任何命令</translation>
    </message>
    <message>
        <source>Motor %1: its values could not be read (%2): nothing was moved</source>
        <translation>电机 %1：无法读取其参数（%2）：没有运动</translation>
    </message>
    <message>
        <source>Motor %1: its step angle, microsteps or pitch is 0: the axis cannot be proven</source>
        <translation>电机 %1：步距角、细分或螺距为 0：无法验证该轴</translation>
    </message>
    <message>
        <source>Motor %1: the test speed could not be written (%2)</source>
        <translation>电机 %1：无法写入测试转速（%2）</translation>
    </message>
    <message>
        <source>This register map has no input %1</source>
        <translation>此寄存器表中没有输入 %1</translation>
    </message>
    <message>
        <source>the home input could not be read (%1)</source>
        <translation>无法读取原点输入（%1）</translation>
    </message>
    <message>
        <source>speed %1 %2, acceleration %3 %4</source>
        <translation>速度 %1 %2，加速度 %3 %4</translation>
    </message>
    <message>
        <source>Motor %1&apos;s own %2 are as they were.</source>
        <translation>电机 %1 原来的参数（%2）保持不变。</translation>
    </message>
    <message>
        <source>Motor %1&apos;s own %2 could not be put back: not connected. Write them again once the controller answers.</source>
        <translation>电机 %1 原来的参数（%2）未能恢复：未连接。控制器应答后请重新写入。</translation>
    </message>
    <message>
        <source>Motor %1&apos;s own %2 could not be put back: %3</source>
        <translation>电机 %1 原来的参数（%2）未能恢复：%3</translation>
    </message>
    <message>
        <source>Motor %1&apos;s own %2 are back (verified).</source>
        <translation>电机 %1 原来的参数（%2）已恢复（已校验）。</translation>
    </message>
    <message>
        <source>Stopped: the motor was stopped</source>
        <translation>已停止：电机已被停止</translation>
    </message>
    <message>
        <source>E-STOP: the test ended at once</source>
        <translation>急停：测试立即结束</translation>
    </message>
    <message>
        <source>The link was lost: the test ended</source>
        <translation>通信中断：测试已结束</translation>
    </message>
    <message>
        <source>The controller restarted: the test ended</source>
        <translation>控制器已重新启动：测试已结束</translation>
    </message>
    <message>
        <source>Motor %1 has no home input set (%2 is 0): the test references on the home switch, so nothing was moved</source>
        <translation>电机 %1 未设定原点输入（%2 为 0）：测试要以原点开关为参考，因此没有运动</translation>
    </message>
</context>
<context>
    <name>stepcom::ProofResult</name>
    <message>
        <source>%1. %2</source>
        <translation>%1。%2</translation>
    </message>
</context>
<context>
    <name>stepcom::Reader</name>
    <message>
        <source>unknown key</source>
        <translation>未知的键</translation>
    </message>
    <message>
        <source>must be a number</source>
        <translation>必须是数字</translation>
    </message>
    <message>
        <source>%1 is out of range (%2 to %3)</source>
        <translation>%1 超出范围（%2 到 %3）</translation>
    </message>
    <message>
        <source>must be a whole number</source>
        <translation>必须是整数</translation>
    </message>
    <message>
        <source>must be true or false</source>
        <translation>必须是 true 或 false</translation>
    </message>
    <message>
        <source>must be an object</source>
        <translation>必须是对象</translation>
    </message>
</context>
<context>
    <name>stepcom::ReferenceTracker</name>
    <message>
        <source>referenced</source>
        <translation>已建立参考点</translation>
    </message>
    <message>
        <source>not referenced (not homed yet)</source>
        <translation>未建立参考点（尚未回零）</translation>
    </message>
    <message>
        <source>not referenced (homing ended without the home input)</source>
        <translation>未建立参考点（回零结束时原点输入未接通）</translation>
    </message>
    <message>
        <source>not referenced (homing was interrupted)</source>
        <translation>未建立参考点（回零被中断）</translation>
    </message>
    <message>
        <source>not referenced (E-STOP)</source>
        <translation>未建立参考点（急停）</translation>
    </message>
    <message>
        <source>not referenced (coordinates zeroed)</source>
        <translation>未建立参考点（坐标已清零）</translation>
    </message>
    <message>
        <source>not referenced (link lost)</source>
        <translation>未建立参考点（连接丢失）</translation>
    </message>
    <message>
        <source>not referenced (the controller restarted)</source>
        <translation>无参考点（控制器重新启动了）</translation>
    </message>
    <message>
        <source>reference not known (no answer while it moved: the controller may have restarted)</source>
        <translation>参考点未知（运动时没有应答：控制器可能重新启动了）</translation>
    </message>
</context>
<context>
    <name>stepcom::RegisterMap</name>
    <message>
        <source>%1: not a register map file (not a regular file)</source>
        <translation>%1：不是寄存器映射文件（不是普通文件）</translation>
    </message>
    <message>
        <source>%1: %2 bytes is too large for a register map (at most %3 MiB)</source>
        <translation>%1：%2 字节对寄存器映射来说太大（最多 %3 MiB）</translation>
    </message>
</context>
<context>
    <name>stepcom::ReplayBar</name>
    <message>
        <source>id %1</source>
        <translation>ID %1</translation>
    </message>
    <message>
        <source>line</source>
        <translation>总线</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <source>Play the log at the chosen speed, or hold it at this moment</source>
        <translation>按所选速度播放日志，或停在此刻</translation>
    </message>
    <message>
        <source>Replay speed</source>
        <translation>回放速度</translation>
    </message>
    <message>
        <source>◀ Frame</source>
        <translation>◀ 帧</translation>
    </message>
    <message>
        <source>The frame before this moment</source>
        <translation>此刻之前的一帧</translation>
    </message>
    <message>
        <source>Frame ▶</source>
        <translation>帧 ▶</translation>
    </message>
    <message>
        <source>The next frame after this moment</source>
        <translation>此刻之后的下一帧</translation>
    </message>
    <message>
        <source>Moment of the log</source>
        <translation>日志中的时刻</translation>
    </message>
    <message>
        <source>Time from the start of the log (clock time)</source>
        <translation>从日志开始起的时间（时钟时间）</translation>
    </message>
    <message>
        <source>◀ Event</source>
        <translation>◀ 事件</translation>
    </message>
    <message>
        <source>The event before this moment</source>
        <translation>此刻之前的事件</translation>
    </message>
    <message>
        <source>Event ▶</source>
        <translation>事件 ▶</translation>
    </message>
    <message>
        <source>The next event after this moment</source>
        <translation>此刻之后的下一个事件</translation>
    </message>
    <message>
        <source>Events of the log</source>
        <translation>日志中的事件</translation>
    </message>
    <message>
        <source>Writes, commands, E-STOPs, errors, the link and restarts; choose one to see that moment</source>
        <translation>写入、命令、急停、错误、连接和重启；选择一项即可查看那一时刻</translation>
    </message>
    <message>
        <source>&amp;Device:</source>
        <translation>设备(&amp;D)：</translation>
    </message>
    <message>
        <source>The controller of the line shown on the pages</source>
        <translation>页面上显示的总线上的控制器</translation>
    </message>
    <message>
        <source>Close replay</source>
        <translation>关闭回放</translation>
    </message>
    <message>
        <source>Leave the replay; the window is empty again, ready to connect</source>
        <translation>退出回放；窗口恢复为空，可以连接</translation>
    </message>
    <message numerus="yes">
        <source>… %n more event(s): Event ▶ reaches them</source>
        <translation>
            <numerusform>… 还有 %n 个事件：用“事件 ▶”查看</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stepcom::ReplayDecoder</name>
    <message>
        <source>late answer (discarded): %1</source>
        <translation>迟到的应答（已丢弃）：%1</translation>
    </message>
    <message>
        <source>no answer: %1</source>
        <translation>无应答：%1</translation>
    </message>
    <message>
        <source>E-STOP sent, not acknowledged</source>
        <translation>已发送急停，未得到确认</translation>
    </message>
    <message>
        <source>refused (%1): %2</source>
        <translation>被拒绝（%1）：%2</translation>
    </message>
    <message>
        <source>E-STOP acknowledged</source>
        <translation>急停已确认</translation>
    </message>
</context>
<context>
    <name>stepcom::ReplayLog</name>
    <message>
        <source>lines not of a session log, skipped: %1 (line %2)</source>
        <translation>不属于会话日志的行，已跳过：%1（第 %2 行）</translation>
    </message>
    <message>
        <source>the log ends in the middle of line %1 (cut short?): that line is left out</source>
        <translation>日志在第 %1 行中间结束（被截断？）：该行已略去</translation>
    </message>
    <message>
        <source>events not listed (too many): %1</source>
        <translation>未列出的事件（过多）：%1</translation>
    </message>
    <message>
        <source>line %1: the log was recorded with the register map %2, not with %3 (open it with that map)</source>
        <translation>第 %1 行：该日志是用寄存器映射表 %2 记录的，而不是 %3（请用该映射表打开）</translation>
    </message>
    <message>
        <source>%1: no such file</source>
        <translation>%1：文件不存在</translation>
    </message>
    <message>
        <source>%1 is empty</source>
        <translation>%1 为空</translation>
    </message>
    <message>
        <source>%1 is a zip file, not a session log (a support bundle? open it as one)</source>
        <translation>%1 是 zip 文件，不是会话日志（是支持包吗？请按支持包打开）</translation>
    </message>
    <message>
        <source>%1 holds no frames, only its header</source>
        <translation>%1 只有文件头，没有报文</translation>
    </message>
    <message>
        <source>%1 is not a StepCom session log: not one of its lines is one (%2 lines)</source>
        <translation>%1 不是 StepCom 会话日志：没有一行符合格式（共 %2 行）</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>opening %1 was cancelled</source>
        <translation>已取消打开 %1</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a time: give seconds from the start (12.5) or a clock time hh:mm:ss[.mmm]</source>
        <translation>“%1”不是时间：请给出距开始的秒数（12.5）或钟点时间 hh:mm:ss[.mmm]</translation>
    </message>
    <message>
        <source>%1 is before the log&apos;s start (%2)</source>
        <translation>%1 早于日志的开始时间（%2）</translation>
    </message>
</context>
<context>
    <name>stepcom::ReplayMode</name>
    <message>
        <source>Replay of %1 — nothing is written or moved. The pages show what the log says the controller held at the moment chosen below; connect or close the replay to work with a controller.</source>
        <translation>回放 %1 — 不写入任何参数，也不运动。页面显示日志记录的控制器在下方所选时刻的状态；如需操作控制器，请连接或关闭回放。</translation>
    </message>
    <message>
        <source>Open session &amp;log…</source>
        <translation>打开会话日志(&amp;L)…</translation>
    </message>
    <message>
        <source>Replay a session log or a support bundle: see what the window showed then, without a controller (%1)</source>
        <translation>回放会话日志或支持包：无需控制器即可看到当时窗口显示的内容（%1）</translation>
    </message>
    <message>
        <source>Close re&amp;play</source>
        <translation>关闭回放(&amp;P)</translation>
    </message>
    <message>
        <source>A session log is being opened already.</source>
        <translation>已在打开一个会话日志。</translation>
    </message>
    <message>
        <source>Disconnect from the controller before replaying a log: a replay shows the log&apos;s values where the controller&apos;s are.</source>
        <translation>回放日志前请先断开控制器：回放会在控制器数值的位置显示日志中的数值。</translation>
    </message>
    <message>
        <source>Close the profile file before replaying a log.</source>
        <translation>回放日志前请先关闭参数文件。</translation>
    </message>
    <message>
        <source>Open session log</source>
        <translation>打开会话日志</translation>
    </message>
    <message>
        <source>Session logs and support bundles (*.log *.txt *.zip);;All files (*)</source>
        <translation>会话日志和支持包 (*.log *.txt *.zip);;所有文件 (*)</translation>
    </message>
    <message>
        <source>%1 cannot be replayed: %2</source>
        <translation>无法回放 %1：%2</translation>
    </message>
    <message numerus="yes">
        <source>%1 holds %n session log(s). Which one to replay?</source>
        <translation>
            <numerusform>%1 包含 %n 个会话日志。要回放哪一个？</numerusform>
        </translation>
    </message>
    <message>
        <source>Reading %1…</source>
        <translation>正在读取 %1…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Opening %1 was cancelled.</source>
        <translation>已取消打开 %1。</translation>
    </message>
    <message numerus="yes">
        <source>Replaying %1: %2 s, %n event(s).</source>
        <translation>
            <numerusform>正在回放 %1：%2 秒，%n 个事件。</numerusform>
        </translation>
    </message>
    <message>
        <source>Warning: %1.</source>
        <translation>警告：%1。</translation>
    </message>
    <message>
        <source>Replay of %1 closed.</source>
        <translation>已关闭 %1 的回放。</translation>
    </message>
    <message>
        <source>Its last error, at %1: %2.</source>
        <translation>其最后一次错误发生在 %1：%2。</translation>
    </message>
    <message>
        <source>At this moment the link is up.</source>
        <translation>此刻连接正常。</translation>
    </message>
    <message>
        <source>At this moment the link is down.</source>
        <translation>此刻连接已断开。</translation>
    </message>
    <message>
        <source>Id %1 answers.</source>
        <translation>ID %1 有应答。</translation>
    </message>
    <message>
        <source>Id %1 does not answer.</source>
        <translation>ID %1 无应答。</translation>
    </message>
    <message>
        <source>StepCom is trying to reconnect to the controller: cancel that before replaying a log.</source>
        <translation>StepCom 正在尝试重新连接控制器：回放日志前请先取消。</translation>
    </message>
    <message>
        <source>replay: %1</source>
        <translation>回放：%1</translation>
    </message>
</context>
<context>
    <name>stepcom::ReplayState</name>
    <message>
        <source>(unknown)</source>
        <translation>（未知）</translation>
    </message>
</context>
<context>
    <name>stepcom::ReportFile</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>%1: the report is written as .pdf or .html, not .%2</source>
        <translation>%1：报告只能保存为 .pdf 或 .html，不能是 .%2</translation>
    </message>
</context>
<context>
    <name>stepcom::RestartWatch</name>
    <message>
        <source>it answers again after %1 s without an answer</source>
        <translation>它在 %1 s 没有应答之后重新应答</translation>
    </message>
    <message>
        <source>its positions went back to 0 where an axis stood still, with no command</source>
        <translation>在有轴静止、没有命令的情况下，它的位置回到了 0</translation>
    </message>
    <message>
        <source>motor %1 stood still at %2 and reads %3</source>
        <translation>电机 %1 原停在 %2，现在读数为 %3</translation>
    </message>
    <message>
        <source>motor %1 stood still at %2</source>
        <translation>电机 %1 原停在 %2</translation>
    </message>
    <message>
        <source>motor %1 was moving and reads %2</source>
        <translation>电机 %1 原在运动，现在读数为 %2</translation>
    </message>
    <message>
        <source>; </source>
        <comment>between what was seen</comment>
        <translation>；</translation>
    </message>
</context>
<context>
    <name>stepcom::RoundTrips</name>
    <message>
        <source>%1-%2 ms (median %3 ms)</source>
        <translation>%1-%2 ms（中位数 %3 ms）</translation>
    </message>
</context>
<context>
    <name>stepcom::RtuTransport</name>
    <message>
        <source>%1 is not a serial port (give the adapter&apos;s device, e.g. /dev/ttyUSB0 or a /dev/serial/by-id/ link)</source>
        <translation>%1 不是串口（请给出适配器的设备，例如 /dev/ttyUSB0 或 /dev/serial/by-id/ 下的链接）</translation>
    </message>
    <message>
        <source>the converter closed the connection</source>
        <translation>转换器关闭了连接</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <source>bytes that arrived between two requests</source>
        <translation>在两个请求之间到达的字节</translation>
    </message>
    <message>
        <source>bytes that are no answer frame</source>
        <translation>不是应答帧的字节</translation>
    </message>
    <message>
        <source>an answer with a bad checksum (CRC)</source>
        <translation>校验和（CRC）错误的应答</translation>
    </message>
    <message>
        <source>an answer from device %1, not %2</source>
        <translation>来自站号 %1 而不是 %2 的应答</translation>
    </message>
    <message>
        <source>a late answer to an earlier request</source>
        <translation>之前某个请求的迟到应答</translation>
    </message>
    <message>
        <source>an incomplete answer</source>
        <translation>不完整的应答</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceCheck</name>
    <message>
        <source>%1: the run has too many steps to check its positions (more than %2): make it shorter or use fewer cycles</source>
        <translation>%1：运行的步骤太多，无法检查其位置（超过 %2）：请缩短或减少循环次数</translation>
    </message>
    <message>
        <source>motor %1 would go to %2 %3, outside the file&apos;s limits (%4 .. %5 %3)</source>
        <translation>电机 %1 将到达 %2 %3，超出文件的限位（%4 .. %5 %3）</translation>
    </message>
    <message>
        <source>the controller&apos;s homing order (40177, 40178) names no motor: &quot;home&quot;: &quot;order&quot; homes nothing</source>
        <translation>控制器的回零顺序（40177、40178）未指定电机：&quot;home&quot;: &quot;order&quot; 不会使任何电机回零</translation>
    </message>
    <message>
        <source>motor %1 is not referenced: a move_to needs a home step before it (or the axis referenced already)</source>
        <translation>电机 %1 未建立参考：move_to 之前需要回零步骤（或该轴已建立参考）</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceEditor</name>
    <message>
        <source>&amp;Add step</source>
        <translation>添加步骤(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Remove</source>
        <translation>删除(&amp;R)</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>上移</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>下移</translation>
    </message>
    <message>
        <source>Into the loop above</source>
        <translation>移入上面的循环</translation>
    </message>
    <message>
        <source>Out of the loop</source>
        <translation>移出循环</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>步骤</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceMove</name>
    <message>
        <source>A move is still running: wait for it to end</source>
        <translation>仍有运动在进行：请等待其结束</translation>
    </message>
</context>
<context>
    <name>stepcom::SequencePage</name>
    <message>
        <source>Sequence</source>
        <translation>序列</translation>
    </message>
    <message>
        <source>(new sequence)</source>
        <translation>（新序列）</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>点位</translation>
    </message>
    <message>
        <source>Path</source>
        <translation>路径</translation>
    </message>
    <message>
        <source>The sequence has changes that are not saved. Discard them?</source>
        <translation>序列有尚未保存的修改。要放弃这些修改吗？</translation>
    </message>
    <message>
        <source>Open a sequence</source>
        <translation>打开序列</translation>
    </message>
    <message>
        <source>%1 was not opened: the sequence is as it was.</source>
        <translation>未打开 %1：序列保持原样。</translation>
    </message>
    <message>
        <source>Save the sequence</source>
        <translation>保存序列</translation>
    </message>
    <message>
        <source>Not saved: the sequence could not be read back as a file.</source>
        <translation>未保存：序列无法作为文件读回。</translation>
    </message>
    <message>
        <source>%1 was not saved: %2</source>
        <translation>未保存 %1：%2</translation>
    </message>
    <message>
        <source>Any earlier file there is as it was.</source>
        <translation>该位置原有的文件保持不变。</translation>
    </message>
    <message>
        <source>StepCom sequences (*.stepseq);;All files (*)</source>
        <translation>StepCom 序列 (*.stepseq);;所有文件 (*)</translation>
    </message>
    <message>
        <source>StepCom sequences (*.stepseq)</source>
        <translation>StepCom 序列 (*.stepseq)</translation>
    </message>
    <message>
        <source>a new sequence, not saved</source>
        <translation>新序列，尚未保存</translation>
    </message>
    <message>
        <source>Sequence: %1%2</source>
        <translation>序列：%1%2</translation>
    </message>
    <message>
        <source> (changed)</source>
        <translation>（已修改）</translation>
    </message>
    <message>
        <source>motor %1 %2 .. %3 %4</source>
        <translation>电机 %1 %2 .. %3 %4</translation>
    </message>
    <message>
        <source>The file sets no limits of its own; StepCom&apos;s travel limits (Jog page) apply.</source>
        <translation>文件没有自己的限位；适用 StepCom 的软件行程限位（点动页面）。</translation>
    </message>
    <message>
        <source>The file&apos;s limits: %1; StepCom&apos;s travel limits apply too.</source>
        <translation>文件的限位：%1；StepCom 的软件行程限位同样适用。</translation>
    </message>
    <message>
        <source>Path (motor 1 across, motor 2 up)</source>
        <translation>路径（电机 1 为横轴，电机 2 为纵轴）</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>步骤</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>All outputs &amp;off when the run stops</source>
        <translation>运行停止时关闭全部输出(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>新建(&amp;N)</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>打开(&amp;O)…</translation>
    </message>
    <message>
        <source>Sa&amp;ve</source>
        <translation>保存(&amp;V)</translation>
    </message>
    <message>
        <source>Save &amp;as…</source>
        <translation>另存为(&amp;A)…</translation>
    </message>
    <message>
        <source>motor 1</source>
        <translation>电机 1</translation>
    </message>
    <message>
        <source>motor 2</source>
        <translation>电机 2</translation>
    </message>
    <message>
        <source>No steps yet: jog to each point and teach it, then Add step (or open a .stepseq file).</source>
        <translation>还没有步骤：点动到每个点位并示教，然后“添加步骤”（或打开 .stepseq 文件）。</translation>
    </message>
    <message>
        <source>Teach this point (%1, %2)</source>
        <translation>示教此点 (%1, %2)</translation>
    </message>
    <message>
        <source>Point %1 taught at the place clicked.</source>
        <translation>点 %1 已按点击位置示教。</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceParser</name>
    <message>
        <source>a true/false</source>
        <translation>true/false</translation>
    </message>
    <message>
        <source>a number</source>
        <translation>数字</translation>
    </message>
    <message>
        <source>a text</source>
        <translation>文本</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>列表</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>对象</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>空值</translation>
    </message>
    <message>
        <source>unknown key &quot;%1&quot; (allowed here: %2)</source>
        <translation>未知的键“%1”（此处允许：%2）</translation>
    </message>
    <message>
        <source>must be %1, not %2</source>
        <translation>必须是%1，而不是%2</translation>
    </message>
    <message>
        <source>a whole number</source>
        <translation>整数</translation>
    </message>
    <message>
        <source>must be a whole number from %1 to %2, not %3</source>
        <translation>必须是 %1 到 %2 之间的整数，而不是 %3</translation>
    </message>
    <message>
        <source>unknown axis &quot;%1&quot; (this controller has motor1 .. motor%2)</source>
        <translation>未知的轴“%1”（此控制器有 motor1 .. motor%2）</translation>
    </message>
    <message>
        <source>an object {&quot;motor1&quot;: …}</source>
        <translation>对象 {&quot;motor1&quot;: …}</translation>
    </message>
    <message>
        <source>names no axis</source>
        <translation>未指定轴</translation>
    </message>
    <message>
        <source>an object of named points</source>
        <translation>由命名点组成的对象</translation>
    </message>
    <message>
        <source>an object {&quot;motor1&quot;: {&quot;min&quot;: …, &quot;max&quot;: …}}</source>
        <translation>对象 {&quot;motor1&quot;: {&quot;min&quot;: …, &quot;max&quot;: …}}</translation>
    </message>
    <message>
        <source>an object {&quot;min&quot;: …, &quot;max&quot;: …}</source>
        <translation>对象 {&quot;min&quot;: …, &quot;max&quot;: …}</translation>
    </message>
    <message>
        <source>sets neither min nor max</source>
        <translation>既未设置 min 也未设置 max</translation>
    </message>
    <message>
        <source>must be &quot;leave&quot; or &quot;all_off&quot;</source>
        <translation>必须是 &quot;leave&quot; 或 &quot;all_off&quot;</translation>
    </message>
    <message>
        <source>a list of steps</source>
        <translation>步骤列表</translation>
    </message>
    <message>
        <source>holds no step</source>
        <translation>不含任何步骤</translation>
    </message>
    <message>
        <source>a step (an object)</source>
        <translation>步骤（对象）</translation>
    </message>
    <message>
        <source>unknown key &quot;%1&quot;: a step needs one of %2</source>
        <translation>未知的键“%1”：步骤需要 %2 之一</translation>
    </message>
    <message>
        <source>not a step: it needs one of %1</source>
        <translation>不是步骤：需要 %1 之一</translation>
    </message>
    <message>
        <source>one step does one thing, not %1</source>
        <translation>一个步骤只做一件事，而不是 %1</translation>
    </message>
    <message>
        <source>&quot;order&quot; or a motor (&quot;motor1&quot;)</source>
        <translation>&quot;order&quot; 或电机（&quot;motor1&quot;）</translation>
    </message>
    <message>
        <source>unknown point &quot;%1&quot; (the file&apos;s points: %2)</source>
        <translation>未知的点“%1”（文件中的点：%2）</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>the controller has no input %1 (it has IN1 .. IN%2)</source>
        <translation>控制器没有输入 %1（它有 IN1 .. IN%2）</translation>
    </message>
    <message>
        <source>the controller has no output %1 (it has outputs 1 .. %2)</source>
        <translation>控制器没有输出 %1（它有输出 1 .. %2）</translation>
    </message>
    <message>
        <source>the controller cannot switch output %1 alone (only outputs with their own on/off command: output 1); use &quot;outputs&quot;: &quot;all_on&quot; or &quot;all_off&quot;</source>
        <translation>控制器不能单独切换输出 %1（只有带独立开/关命令的输出可以：输出 1）；请用 &quot;outputs&quot;: &quot;all_on&quot; 或 &quot;all_off&quot;</translation>
    </message>
    <message>
        <source>needs &quot;on&quot;: true or false</source>
        <translation>需要 &quot;on&quot;: true 或 false</translation>
    </message>
    <message>
        <source>true or false</source>
        <translation>true 或 false</translation>
    </message>
    <message>
        <source>a number of seconds</source>
        <translation>秒数</translation>
    </message>
    <message>
        <source>must be more than 0 and at most 86400 s</source>
        <translation>必须大于 0 且不超过 86400 秒</translation>
    </message>
    <message>
        <source>must be &quot;all_on&quot; or &quot;all_off&quot;</source>
        <translation>必须是 &quot;all_on&quot; 或 &quot;all_off&quot;</translation>
    </message>
    <message>
        <source>a repeat needs &quot;steps&quot;</source>
        <translation>repeat 需要 &quot;steps&quot;</translation>
    </message>
    <message>
        <source>line %1, column %2</source>
        <translation>第 %1 行第 %2 列</translation>
    </message>
    <message>
        <source>%1: not valid JSON at %2: %3</source>
        <translation>%1：在 %2 处不是有效的 JSON：%3</translation>
    </message>
    <message>
        <source>%1: a sequence file is one JSON object</source>
        <translation>%1：序列文件是一个 JSON 对象</translation>
    </message>
    <message>
        <source>not a sequence file (&quot;format&quot; must be &quot;%1&quot;)</source>
        <translation>不是序列文件（&quot;format&quot; 必须是 &quot;%1&quot;）</translation>
    </message>
    <message>
        <source>version %1 is not known (this StepCom reads version %2)</source>
        <translation>未知的版本 %1（此 StepCom 读取版本 %2）</translation>
    </message>
    <message>
        <source>the file has no &quot;steps&quot;</source>
        <translation>文件中没有 &quot;steps&quot;</translation>
    </message>
    <message>
        <source>%1: cannot be read: %2</source>
        <translation>%1：无法读取：%2</translation>
    </message>
</context>
<context>
    <name>stepcom::SequencePlan</name>
    <message numerus="yes">
        <source>Sequence %1: %n step(s) in the file</source>
        <translation>
            <numerusform>序列 %1：文件中有 %n 个步骤</numerusform>
        </translation>
    </message>
    <message>
        <source>  point %1: %2</source>
        <translation>  点 %1：%2</translation>
    </message>
    <message>
        <source>  limits motor%1: %2 .. %3 %4</source>
        <translation>  电机%1 限位：%2 .. %3 %4</translation>
    </message>
    <message>
        <source>  on a stop: all outputs off</source>
        <translation>  停止时：关闭所有输出</translation>
    </message>
    <message>
        <source>  on a stop: the outputs are left as they are</source>
        <translation>  停止时：输出保持原样</translation>
    </message>
    <message>
        <source>  cycles: %1 (the whole step list each time)</source>
        <translation>  循环：%1（每次运行整个步骤表）</translation>
    </message>
    <message>
        <source>  then the lost-step test (lost-steps) on %1, each referenced on its home switch</source>
        <translation>  然后对 %1 运行丢步测试（lost-steps），每根轴都以其原点开关为参考</translation>
    </message>
</context>
<context>
    <name>stepcom::SequencePoints</name>
    <message>
        <source>motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>Not taught: the position of %1 is not known (connect, and let the status poll read it).</source>
        <translation>未示教：%1 的位置未知（请连接，并等待状态轮询读到它）。</translation>
    </message>
    <message>
        <source>Point %1 taught again at the live position.</source>
        <translation>点 %1 已按实时位置重新示教。</translation>
    </message>
    <message>
        <source>Point %1 taught at the live position; double-click its name to rename it.</source>
        <translation>点 %1 已按实时位置示教；双击名称可重命名。</translation>
    </message>
    <message>
        <source>There is a point %1 already: the name stays %2.</source>
        <translation>已经有点 %1：名称仍为 %2。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot name a point: use 1-40 letters, digits, _ or -.</source>
        <translation>“%1”不能作为点的名称：请使用 1-40 个字母、数字、_ 或 -。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no position: point %2 keeps motor %3 as it was.</source>
        <translation>“%1”不是位置：点 %2 的电机 %3 保持原值。</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>点</translation>
    </message>
    <message>
        <source>Motor %1 (%2)</source>
        <translation>电机 %1 (%2)</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>Jog motor %1:</source>
        <translation>点动电机 %1：</translation>
    </message>
    <message>
        <source>◀ Hold</source>
        <translation>◀ 按住</translation>
    </message>
    <message>
        <source>Hold ▶</source>
        <translation>按住 ▶</translation>
    </message>
    <message>
        <source>Jog motor %1 reverse (hold)</source>
        <translation>电机 %1 反转点动（按住）</translation>
    </message>
    <message>
        <source>Jog motor %1 forward (hold)</source>
        <translation>电机 %1 正转点动（按住）</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>点位</translation>
    </message>
    <message>
        <source>&amp;Teach here</source>
        <translation>示教此处(&amp;T)</translation>
    </message>
    <message>
        <source>A new point at the live position of every motor</source>
        <translation>以各电机的实时位置新建一个点</translation>
    </message>
    <message>
        <source>Teach &amp;selected again</source>
        <translation>重新示教所选点(&amp;S)</translation>
    </message>
    <message>
        <source>Remove point</source>
        <translation>删除点</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceRunPanel</name>
    <message>
        <source>Pausing after the current step…</source>
        <translation>当前步骤之后暂停…</translation>
    </message>
    <message>
        <source>Step %1: %2</source>
        <translation>步骤 %1：%2</translation>
    </message>
    <message>
        <source>Cycle %1 done in %2 s.</source>
        <translation>第 %1 个循环用时 %2 s。</translation>
    </message>
    <message>
        <source>Paused before %1: Step runs it, Resume goes on.</source>
        <translation>在 %1 之前暂停：“单步执行”运行它，“继续”接着运行。</translation>
    </message>
    <message>
        <source>The sequence has problems (listed above): nothing was sent.</source>
        <translation>序列有问题（见上方）：未发送任何内容。</translation>
    </message>
    <message>
        <source>Not connected: nothing was sent.</source>
        <translation>未连接：未发送任何内容。</translation>
    </message>
    <message>
        <source>Run the sequence</source>
        <translation>运行序列</translation>
    </message>
    <message>
        <source>Run it? The machine will move.</source>
        <translation>要运行吗？机器将会运动。</translation>
    </message>
    <message>
        <source>Not started: nothing was sent.</source>
        <translation>未开始：未发送任何内容。</translation>
    </message>
    <message>
        <source>The run could not start: not connected, or one is running.</source>
        <translation>无法开始运行：未连接，或已有运行在进行。</translation>
    </message>
    <message>
        <source>Reading the positions and checking the run…</source>
        <translation>正在读取位置并检查运行…</translation>
    </message>
    <message>
        <source>Cycle — of %1</source>
        <translation>第 — 个循环（共 %1 个）</translation>
    </message>
    <message>
        <source>Running sequence: cycle %1 of %2</source>
        <translation>正在运行序列：第 %1 个循环（共 %2 个）</translation>
    </message>
    <message>
        <source>Running sequence: cycle %1 of %2, step %3</source>
        <translation>正在运行序列：第 %1 个循环（共 %2 个），第 %3 步</translation>
    </message>
    <message>
        <source>%1 (at %2)</source>
        <translation>%1（在 %2）</translation>
    </message>
    <message>
        <source>Cycles done: %1 of %2; cycle time min %3 s, median %4 s, max %5 s</source>
        <translation>完成循环：%1 / %2；循环时间 最短 %3 s，中位 %4 s，最长 %5 s</translation>
    </message>
    <message>
        <source>Cycles done: %1 of %2</source>
        <translation>完成循环：%1 / %2</translation>
    </message>
    <message>
        <source>Running sequence: the lost-step check</source>
        <translation>正在运行序列：丢步检查</translation>
    </message>
    <message>
        <source>Lost-step check: %1</source>
        <translation>丢步检查：%1</translation>
    </message>
    <message>
        <source>C&amp;ycles:</source>
        <translation>循环次数(&amp;Y)：</translation>
    </message>
    <message>
        <source>S&amp;ingle step</source>
        <translation>单步(&amp;I)</translation>
    </message>
    <message>
        <source>Pause after every step; Step runs the next one</source>
        <translation>每一步之后暂停；“单步执行”运行下一步</translation>
    </message>
    <message>
        <source>Lost-step &amp;check at the end</source>
        <translation>结束时检查丢步(&amp;C)</translation>
    </message>
    <message>
        <source>After the last cycle, the lost-step test on every axis the sequence moved, each referenced on its home switch</source>
        <translation>最后一个循环之后，对序列移动过的每根轴运行丢步测试，每根轴都以其原点开关为参考</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>运行(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>暂停(&amp;P)</translation>
    </message>
    <message>
        <source>Pause after the step running now</source>
        <translation>在正在执行的步骤之后暂停</translation>
    </message>
    <message>
        <source>S&amp;tep</source>
        <translation>单步执行(&amp;T)</translation>
    </message>
    <message>
        <source>Resu&amp;me</source>
        <translation>继续(&amp;M)</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <source>Not running.</source>
        <translation>未在运行。</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceRunner</name>
    <message>
        <source>%1: the input did not come within %2 s</source>
        <translation>%1：输入未在 %2 秒内到来</translation>
    </message>
    <message>
        <source>E-STOP: every motor and output stopped; the run ended</source>
        <translation>急停：所有电机和输出已停止；运行结束</translation>
    </message>
    <message>
        <source>the link was lost (%1): the run ended; the controller goes on with what it was doing</source>
        <translation>通信中断（%1）：运行结束；控制器会继续执行它正在做的事</translation>
    </message>
    <message>
        <source>the controller restarted (or may have): its positions and references are gone; the run ended</source>
        <translation>控制器已重启（或可能已重启）：其位置和参考已丢失；运行结束</translation>
    </message>
    <message>
        <source>could not read the positions, speeds and homing order (%1): nothing was moved</source>
        <translation>无法读取位置、速度和回零顺序（%1）：未运动任何轴</translation>
    </message>
    <message>
        <source>motor %1 is running</source>
        <translation>电机 %1 正在运行</translation>
    </message>
    <message>
        <source>the run was refused before anything moved: %1</source>
        <translation>运行在任何运动之前被拒绝：%1</translation>
    </message>
    <message numerus="yes">
        <source>%n cycle(s) done</source>
        <translation>
            <numerusform>完成 %n 个循环</numerusform>
        </translation>
    </message>
    <message>
        <source>stopped: the run was interrupted</source>
        <translation>已停止：运行被中断</translation>
    </message>
    <message>
        <source>The motors&apos; own speed or single-move values may not be back: read them before the next run</source>
        <translation>电机自身的速度或单次运动参数可能未恢复：下次运行前请读取它们</translation>
    </message>
    <message>
        <source>this register map has no homing command for %1</source>
        <translation>此寄存器表没有 %1 的回零命令</translation>
    </message>
    <message>
        <source>could not read what the homing is judged on (%1): nothing was moved</source>
        <translation>无法读取判断回零所需的数据（%1）：未运动任何轴</translation>
    </message>
    <message>
        <source>this register map has no command %1</source>
        <translation>此寄存器表没有命令 %1</translation>
    </message>
    <message>
        <source>the speed could not be written and verified (%1)</source>
        <translation>速度无法写入并校验（%1）</translation>
    </message>
    <message>
        <source>the controller did not acknowledge %1: the run ended</source>
        <translation>控制器未确认 %1：运行结束</translation>
    </message>
    <message>
        <source>the outputs could not be read back (%1)</source>
        <translation>无法读回输出（%1）</translation>
    </message>
    <message>
        <source>output %1 still reads OFF after its command</source>
        <translation>命令后输出 %1 仍读为 OFF</translation>
    </message>
    <message>
        <source>output %1 still reads ON after its command</source>
        <translation>命令后输出 %1 仍读为 ON</translation>
    </message>
    <message>
        <source>%1; the outputs the run had switched on read OFF: an E-STOP (or all outputs off) from elsewhere</source>
        <translation>%1；运行打开的输出读为 OFF：来自别处的急停（或全部输出关闭）</translation>
    </message>
    <message>
        <source>the outputs the run had switched on read OFF: an E-STOP (or all outputs off) from elsewhere</source>
        <translation>运行打开的输出读为 OFF：来自别处的急停（或全部输出关闭）</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceStep</name>
    <message>
        <source>home in the set order</source>
        <translation>按设定顺序回零</translation>
    </message>
    <message>
        <source>home %1</source>
        <translation>%1 回零</translation>
    </message>
    <message>
        <source>move to %1</source>
        <translation>移动到 %1</translation>
    </message>
    <message>
        <source>move to %1 (%2)</source>
        <translation>移动到 %1（%2）</translation>
    </message>
    <message>
        <source>move by %1</source>
        <translation>相对移动 %1</translation>
    </message>
    <message>
        <source>wait for IN%1 ON (at most %2 s)</source>
        <translation>等待 IN%1 为 ON（最多 %2 秒）</translation>
    </message>
    <message>
        <source>wait for IN%1 OFF (at most %2 s)</source>
        <translation>等待 IN%1 为 OFF（最多 %2 秒）</translation>
    </message>
    <message>
        <source>wait for IN%1 ON</source>
        <translation>等待 IN%1 为 ON</translation>
    </message>
    <message>
        <source>wait for IN%1 OFF</source>
        <translation>等待 IN%1 为 OFF</translation>
    </message>
    <message>
        <source>output %1 ON</source>
        <translation>输出 %1 ON</translation>
    </message>
    <message>
        <source>output %1 OFF</source>
        <translation>输出 %1 OFF</translation>
    </message>
    <message>
        <source>all outputs ON</source>
        <translation>全部输出 ON</translation>
    </message>
    <message>
        <source>all outputs OFF</source>
        <translation>全部输出 OFF</translation>
    </message>
    <message>
        <source>dwell %1 ms</source>
        <translation>停留 %1 毫秒</translation>
    </message>
    <message numerus="yes">
        <source>repeat %n time(s)</source>
        <translation>
            <numerusform>重复 %n 次</numerusform>
        </translation>
    </message>
    <message>
        <source>speed %1 rpm</source>
        <translation>速度 %1 rpm</translation>
    </message>
</context>
<context>
    <name>stepcom::SequenceStepForm</name>
    <message>
        <source>Home</source>
        <translation>回原点</translation>
    </message>
    <message>
        <source>Move to</source>
        <translation>运行到</translation>
    </message>
    <message>
        <source>Move by</source>
        <translation>相对运行</translation>
    </message>
    <message>
        <source>Wait for an input</source>
        <translation>等待输入</translation>
    </message>
    <message>
        <source>Switch output 1</source>
        <translation>切换输出 1</translation>
    </message>
    <message>
        <source>Switch all outputs</source>
        <translation>切换全部输出</translation>
    </message>
    <message>
        <source>Dwell</source>
        <translation>停留</translation>
    </message>
    <message>
        <source>Repeat (a loop)</source>
        <translation>重复（循环）</translation>
    </message>
    <message>
        <source>Set the speed</source>
        <translation>设定速度</translation>
    </message>
    <message>
        <source>(a position of its own)</source>
        <translation>（单独的位置）</translation>
    </message>
    <message>
        <source>&amp;Step:</source>
        <translation>步骤(&amp;S)：</translation>
    </message>
    <message>
        <source>In the set homing order</source>
        <translation>按设定的回零顺序</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>All ON</source>
        <translation>全部 ON</translation>
    </message>
    <message>
        <source>All OFF</source>
        <translation>全部 OFF</translation>
    </message>
    <message>
        <source>&amp;Home:</source>
        <translation>回原点(&amp;H)：</translation>
    </message>
    <message>
        <source>&amp;Point:</source>
        <translation>点位(&amp;P)：</translation>
    </message>
    <message>
        <source>&amp;Input (IN):</source>
        <translation>输入(&amp;I)（IN）：</translation>
    </message>
    <message>
        <source>&amp;Output:</source>
        <translation>输出(&amp;O)：</translation>
    </message>
    <message>
        <source>State:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <source>Wait for ON (unticked: for OFF)</source>
        <translation>等待 ON（不勾选：等待 OFF）</translation>
    </message>
    <message>
        <source>ON (unticked: OFF)</source>
        <translation>ON（不勾选：OFF）</translation>
    </message>
    <message>
        <source>&amp;Timeout (0: none):</source>
        <translation>超时(&amp;T)（0：不限）：</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>O&amp;utputs:</source>
        <translation>输出(&amp;U)：</translation>
    </message>
    <message>
        <source>&amp;Dwell:</source>
        <translation>停留(&amp;D)：</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>&amp;Times:</source>
        <translation>次数(&amp;T)：</translation>
    </message>
    <message>
        <source>Motor %1:</source>
        <translation>电机 %1：</translation>
    </message>
    <message>
        <source>set</source>
        <translation>设定</translation>
    </message>
    <message>
        <source>moves</source>
        <translation>运动</translation>
    </message>
    <message>
        <source>The controller switches output 1 alone; all %1 outputs together with &quot;Switch all outputs&quot;.</source>
        <translation>控制器只能单独切换输出 1；全部 %1 个输出可用“切换全部输出”一起切换。</translation>
    </message>
</context>
<context>
    <name>stepcom::SerialAdapter</name>
    <message>
        <source>holds received bytes up to its latency timer (16 ms by default), which adds up to 16 ms to every answer; StepCom asks for low latency (1 ms) when it opens the port, and the package&apos;s udev rule sets 1 ms; the kernel&apos;s RS-485 mode is supported by some chips</source>
        <translation>收到的字节最多保留到延迟定时器到期（默认 16 ms），每个应答最多因此多出 16 ms；StepCom 打开端口时请求低延迟（1 ms），安装包的 udev 规则将其设为 1 ms；部分芯片支持内核 RS-485 模式</translation>
    </message>
    <message>
        <source>no latency timer to set; delivers bytes in small USB packets; the driver refuses the kernel&apos;s RS-485 mode (use --rs485 auto with an adapter that switches by itself, or rts)</source>
        <translation>没有可设置的延迟定时器；字节以小 USB 包送达；驱动不支持内核 RS-485 模式（请对能自动切换方向的适配器使用 --rs485 auto，或使用 rts）</translation>
    </message>
    <message>
        <source>no latency timer to set; RS-485 direction, when the adapter has it, is switched by the chip itself (set in its configuration), not by the kernel&apos;s RS-485 mode</source>
        <translation>没有可设置的延迟定时器；适配器若带 RS-485，方向由芯片自身切换（在其配置中设定），而不是由内核 RS-485 模式切换</translation>
    </message>
    <message>
        <source>copies of the chip are common and the driver may refuse them; no kernel RS-485 mode; bytes come in USB packets</source>
        <translation>该芯片的仿制品很常见，驱动可能拒绝它们；没有内核 RS-485 模式；字节以 USB 包送达</translation>
    </message>
    <message>
        <source>a microcontroller&apos;s own USB serial: the baud set may mean nothing to it and the line&apos;s timing is its firmware&apos;s</source>
        <translation>单片机自带的 USB 串口：设置的波特率对它可能没有意义，线路时序取决于其固件</translation>
    </message>
    <message>
        <source>an on-board UART: no USB packets; RS-485 direction through the kernel&apos;s RS-485 mode where the board wires it, else by RTS</source>
        <translation>板载 UART：没有 USB 包延迟；若电路板已连线，RS-485 方向通过内核 RS-485 模式切换，否则通过 RTS</translation>
    </message>
    <message>
        <source>native UART</source>
        <translation>板载 UART</translation>
    </message>
    <message>
        <source>pseudo-terminal</source>
        <translation>伪终端</translation>
    </message>
    <message>
        <source>, latency timer %1 ms</source>
        <translation>，延迟定时器 %1 ms</translation>
    </message>
    <message>
        <source>, serial %1</source>
        <translation>，序列号 %1</translation>
    </message>
</context>
<context>
    <name>stepcom::SerialPorts</name>
    <message>
        <source>S/N %1</source>
        <translation>序列号 %1</translation>
    </message>
    <message>
        <source>Stable name: %1</source>
        <translation>固定名称：%1</translation>
    </message>
    <message>
        <source>Adapter: %1</source>
        <translation>转换器：%1</translation>
    </message>
    <message>
        <source>Manufacturer: %1</source>
        <translation>制造商：%1</translation>
    </message>
    <message>
        <source>Serial number: %1</source>
        <translation>序列号：%1</translation>
    </message>
    <message>
        <source>USB id: %1:%2</source>
        <translation>USB ID：%1:%2</translation>
    </message>
</context>
<context>
    <name>stepcom::SessionBackup</name>
    <message>
        <source>the session ended</source>
        <translation>会话已结束</translation>
    </message>
    <message>
        <source>the controller&apos;s settings could not be read: %1</source>
        <translation>无法读取控制器参数：%1</translation>
    </message>
</context>
<context>
    <name>stepcom::SessionLog</name>
    <message>
        <source>cannot create the log folder %1</source>
        <translation>无法创建日志文件夹 %1</translation>
    </message>
    <message>
        <source>cannot write the session log %1: %2</source>
        <translation>无法写入会话日志 %1：%2</translation>
    </message>
</context>
<context>
    <name>stepcom::SimCommandLine</name>
    <message>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <source>MS</source>
        <translation>毫秒</translation>
    </message>
    <message>
        <source>SHARE</source>
        <translation>比例</translation>
    </message>
    <message>
        <source>Serve Modbus RTU on a new pseudo-terminal (Unix).</source>
        <translation>在新建的伪终端上提供 Modbus RTU 服务（Unix）。</translation>
    </message>
    <message>
        <source>Make PATH a symlink to the pseudo-terminal.</source>
        <translation>在指定路径创建指向该伪终端的符号链接。</translation>
    </message>
    <message>
        <source>PATH</source>
        <translation>路径</translation>
    </message>
    <message>
        <source>Answer whatever baud rate the client set (by default a client whose baud differs from register 40213 gets silence, as on a real line).</source>
        <translation>无论客户端设置何种波特率都应答（默认情况下，客户端波特率与寄存器 40213 不一致时不应答，与真实线路相同）。</translation>
    </message>
    <message>
        <source>Serve Modbus TCP on [HOST:]PORT (127.0.0.1 unless --listen-any; port 0 picks a free one).</source>
        <translation>在 [主机:]端口 上提供 Modbus TCP 服务（未指定 --listen-any 时主机为 127.0.0.1；端口为 0 时自动选择空闲端口）。</translation>
    </message>
    <message>
        <source>[HOST:]PORT</source>
        <translation>[主机:]端口</translation>
    </message>
    <message>
        <source>Listen for TCP on every interface.</source>
        <translation>在所有网络接口上监听 TCP 连接。</translation>
    </message>
    <message>
        <source>Device id 1-255 (overrides the saved one).</source>
        <translation>设备 ID，1-255（覆盖已保存的值）。</translation>
    </message>
    <message>
        <source>The simulator&apos;s flash: saved parameters are loaded from and saved to FILE.</source>
        <translation>仿真器的闪存：从该文件加载已保存的参数，并保存到该文件。</translation>
    </message>
    <message>
        <source>FILE</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>Use the register map FILE instead of the built-in one.</source>
        <translation>使用指定的寄存器映射文件代替内置映射。</translation>
    </message>
    <message>
        <source>Add the bytes&apos; time on a line at N baud to every answer.</source>
        <translation>在每个应答上加上这些字节在波特率为 N 的线路上的传输时间。</translation>
    </message>
    <message>
        <source>Drop a SHARE (0-1 or %) of the answers.</source>
        <translation>按指定比例（0-1 或 %）丢弃应答。</translation>
    </message>
    <message>
        <source>Break the CRC of a SHARE of the answers.</source>
        <translation>按指定比例破坏应答的 CRC。</translation>
    </message>
    <message>
        <source>Answer a SHARE of the requests MS later.</source>
        <translation>按指定比例将请求的应答推迟指定的毫秒数。</translation>
    </message>
    <message>
        <source>SHARE:MS</source>
        <translation>比例:毫秒</translation>
    </message>
    <message>
        <source>Answer a SHARE of the requests with exception CODE instead.</source>
        <translation>按指定比例对请求改为应答指定代码的异常。</translation>
    </message>
    <message>
        <source>SHARE:CODE</source>
        <translation>比例:代码</translation>
    </message>
    <message>
        <source>Hang up the port after every N answers (it comes back, see --hangup-pause).</source>
        <translation>每 N 次应答后挂断端口（之后会恢复，参见 --hangup-pause）。</translation>
    </message>
    <message>
        <source>How long a hung-up port stays away (default 1000).</source>
        <translation>端口挂断后保持断开的时间，单位 ms（默认 1000）。</translation>
    </message>
    <message>
        <source>Seed of the fault dice (default 1).</source>
        <translation>故障随机数种子（默认 1）。</translation>
    </message>
    <message>
        <source>Set an input at start: INn=on|off|pulse (repeatable).</source>
        <translation>启动时设置输入：INn=on|off|pulse（可多次指定）。</translation>
    </message>
    <message>
        <source>INn=STATE</source>
        <translation>INn=状态</translation>
    </message>
    <message>
        <source>Travel of each axis between its limit switches (default 200).</source>
        <translation>各轴在两个限位开关之间的行程（默认 200）。</translation>
    </message>
    <message>
        <source>MM</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>--tcp: &apos;%1&apos; is not [HOST:]PORT</source>
        <translation>--tcp：“%1”不符合 [主机:]端口 格式</translation>
    </message>
    <message>
        <source>--input: &apos;%1&apos; is not INn=on|off|pulse</source>
        <translation>--input：“%1”不符合 INn=on|off|pulse 格式</translation>
    </message>
    <message>
        <source>--%1: &apos;%2&apos; must be a whole number from %3 to %4</source>
        <translation>--%1：“%2”必须是 %3 到 %4 之间的整数</translation>
    </message>
    <message>
        <source>--exception: the code must be 1-255</source>
        <translation>--exception：异常代码必须为 1-255</translation>
    </message>
    <message>
        <source>--travel: &apos;%1&apos; must be a positive distance</source>
        <translation>--travel：“%1”必须是正的距离值</translation>
    </message>
    <message>
        <source>Serve Modbus RTU on the serial PORT (e.g. COM10, one end of a com0com pair, or /dev/ttyUSB1) at the device&apos;s baud rate, 8N1.</source>
        <translation>在串口 PORT 上提供 Modbus RTU 服务（例如 COM10、com0com 虚拟串口对的一端或 /dev/ttyUSB1），使用设备的波特率，8N1。</translation>
    </message>
    <message>
        <source>PORT</source>
        <translation>端口</translation>
    </message>
    <message>
        <source>--serial: no port given</source>
        <translation>--serial：未指定端口</translation>
    </message>
    <message>
        <source>--serial: give either --serial or --pty/--link, not both</source>
        <translation>--serial：只能指定 --serial 或 --pty/--link 之一，不能同时指定</translation>
    </message>
    <message>
        <source>--corrupt-crc works on the pseudo-terminal only, not with --serial</source>
        <translation>--corrupt-crc 仅适用于伪终端，不能与 --serial 同时使用</translation>
    </message>
    <message>
        <source>Several controllers on the one port, one per id (e.g. 1,2,3 or 1-3); a repeated id is a collision: both answer at once.</source>
        <translation>在同一个端口上模拟多台控制器，每个 ID 一台（例如 1,2,3 或 1-3）；重复的 ID 即为冲突：两台同时应答。</translation>
    </message>
    <message>
        <source>IDS</source>
        <translation>ID列表</translation>
    </message>
    <message>
        <source>--ids: give either --id or --ids, not both</source>
        <translation>--ids：只能给 --id 或 --ids 之一，不能同时给</translation>
    </message>
    <message>
        <source>Serve Modbus RTU frames over plain TCP on [HOST:]PORT, as a transparent RS-485/Ethernet converter passes them on (port 0 picks a free one).</source>
        <translation>在 [主机:]端口 上通过普通 TCP 提供 Modbus RTU 帧，如同透明模式的 RS-485/以太网转换器那样转发（端口 0 表示任选一个空闲端口）。</translation>
    </message>
    <message>
        <source>Send every byte the client sends straight back to it first, as a half-duplex USB-RS485 adapter without echo suppression does (pty and --rtu-tcp).</source>
        <translation>先把客户端发送的每个字节原样送回给它，就像没有回显抑制的半双工 USB-RS485 适配器那样（伪终端和 --rtu-tcp）。</translation>
    </message>
    <message>
        <source>--rtu-tcp and --tcp must listen on the same host</source>
        <translation>--rtu-tcp 和 --tcp 必须监听同一个主机</translation>
    </message>
    <message>
        <source>--echo works on the pseudo-terminal and --rtu-tcp, not with --serial</source>
        <translation>--echo 只用于伪终端和 --rtu-tcp，不能与 --serial 一起使用</translation>
    </message>
    <message>
        <source>Refuse a read that covers a reserved register (exception 02): only the manual&apos;s listed registers can be read.</source>
        <translation>拒绝覆盖保留寄存器的读取（异常 02）：只能读取说明书列出的寄存器。</translation>
    </message>
    <message>
        <source>Be a firmware without this listed register (a key or a number such as 40110): reads and writes covering it get exception 02. Repeatable.</source>
        <translation>模拟缺少这个已列出寄存器的固件（键名或编号，例如 40110）：覆盖它的读写返回异常 02。可重复。</translation>
    </message>
    <message>
        <source>REGISTER</source>
        <translation>寄存器</translation>
    </message>
    <message>
        <source>The controller&apos;s answer time: its answer leaves MS after a request (default: the map&apos;s, 35, as the manual asks; other firmware answers in 2-20 ms; 0: as fast as it can).</source>
        <translation>控制器的应答时间：收到请求后经过指定的毫秒数发出应答（默认：寄存器映射中的值，35，即说明书的要求；其他固件在 2-20 ms 内应答；0：尽快应答）。</translation>
    </message>
    <message>
        <source>Coil PLC (e.g. 96, save) acts at once but answers MS later, as firmware writing its flash first. Repeatable.</source>
        <translation>线圈 PLC（例如 96，保存参数）立即执行，但应答推迟指定的毫秒数，如同先写闪存再应答的固件。可重复。</translation>
    </message>
    <message>
        <source>PLC:MS</source>
        <translation>PLC:毫秒</translation>
    </message>
    <message>
        <source>Switch the 24 V off AT seconds after start for OFF seconds: silence, then the saved parameters, positions 0, nothing homed. Repeatable.</source>
        <translation>启动后 AT 秒切断 24 V 电源，持续 OFF 秒：期间不应答，之后恢复为已保存的参数，坐标为 0，均未回原点。可重复。</translation>
    </message>
    <message>
        <source>AT:OFF</source>
        <translation>AT:OFF</translation>
    </message>
    <message>
        <source>--power-cycle: &apos;%1&apos; is not AT:OFF (seconds after start, 0-86400, and seconds off, up to 3600; e.g. 10:3)</source>
        <translation>--power-cycle：“%1”不符合 AT:OFF 格式（启动后的秒数 0-86400，断电秒数最多 3600；例如 10:3）</translation>
    </message>
    <message>
        <source>--slow-coil: &apos;%1&apos; is not PLC:MS (a coil number such as 96 and milliseconds 0-600000)</source>
        <translation>--slow-coil：“%1”不符合 PLC:毫秒 格式（线圈编号如 96，毫秒数 0-600000）</translation>
    </message>
    <message>
        <source>--slow-coil: &apos;%1&apos;: %2 is no coil of the map</source>
        <translation>--slow-coil：“%1”：%2 不是寄存器表中的线圈</translation>
    </message>
    <message>
        <source>Serve a line of N pseudo-terminals: every byte one program sends reaches the others and the controller, as on RS-485 (a master and a listener).</source>
        <translation>提供由 N 个伪终端组成的线路：一个程序发送的每个字节都会到达其他程序和控制器，如同 RS-485（一个主站和一个监听者）。</translation>
    </message>
    <message>
        <source>--line: &apos;%1&apos; is not a number of ptys from 1 to 32</source>
        <translation>--line：“%1”不是 1 到 32 之间的伪终端数量</translation>
    </message>
    <message>
        <source>With --line: the parties numbered in LIST (e.g. 2 or 1,3) hear every byte they send back first, as through an adapter without echo suppression.</source>
        <translation>与 --line 一起使用：LIST 中编号的端口（如 2 或 1,3）先听到自己发出的每个字节，如同经过没有回显抑制的适配器。</translation>
    </message>
    <message>
        <source>LIST</source>
        <translation>列表</translation>
    </message>
    <message>
        <source>--line-echo needs --line N</source>
        <translation>--line-echo 需要 --line N</translation>
    </message>
    <message>
        <source>--line-echo: &apos;%1&apos; is not a party of the line (1 to %2)</source>
        <translation>--line-echo：“%1”不是线路上的端口（1 到 %2）</translation>
    </message>
    <message>
        <source>The machine&apos;s mechanics from FILE (format stepcom-sim-machine): motor limits (stalls), backlash, switches, hard stops, wiring.</source>
        <translation>从 FILE 读取机器的机械特性（格式 stepcom-sim-machine）：电机极限（失步）、反向间隙、开关、机械硬限位、接线。</translation>
    </message>
    <message>
        <source>Keep what really happened (count, rotor, carriage, lost steps, switches) as JSON in FILE, rewritten when it changes (at most every 50 ms).</source>
        <translation>把实际发生的情况（计数、转子、滑台、丢步、开关）以 JSON 保存在 FILE 中，有变化时重写（最多每 50 ms 一次）。</translation>
    </message>
    <message>
        <source>--truth-out: no file given</source>
        <translation>--truth-out：没有给出文件</translation>
    </message>
</context>
<context>
    <name>stepcom::SimConsole</name>
    <message>
        <source>the simulator is not running</source>
        <translation>仿真器未运行</translation>
    </message>
    <message>
        <source>usage: hangup [MS]</source>
        <translation>用法：hangup [毫秒]</translation>
    </message>
    <message>
        <source>hanging up</source>
        <translation>正在挂断</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos; (try help)</source>
        <translation>未知命令“%1”（请输入 help 查看帮助）</translation>
    </message>
    <message>
        <source>usage: in N on|off|pulse</source>
        <translation>用法：in N on|off|pulse</translation>
    </message>
    <message>
        <source>usage: in N on|off|pulse, N from 1 to %1</source>
        <translation>用法：in N on|off|pulse，N 为 1 到 %1</translation>
    </message>
    <message>
        <source>IN%1 is %2</source>
        <translation>IN%1：%2</translation>
    </message>
    <message>
        <source>on</source>
        <translation>开 (ON)</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关 (OFF)</translation>
    </message>
    <message>
        <source>usage: get KEY</source>
        <translation>用法：get 键名</translation>
    </message>
    <message>
        <source>%1: no such register</source>
        <translation>%1：没有此寄存器</translation>
    </message>
    <message>
        <source>usage: set KEY VALUE</source>
        <translation>用法：set 键名 值</translation>
    </message>
    <message>
        <source>usage: do COMMAND</source>
        <translation>用法：do 命令</translation>
    </message>
    <message>
        <source>done: %1</source>
        <translation>已执行：%1</translation>
    </message>
    <message>
        <source>usage: place N MM</source>
        <translation>用法：place N 位置</translation>
    </message>
    <message>
        <source>carriage %1 at %2</source>
        <translation>滑台 %1 位于 %2</translation>
    </message>
    <message>
        <source>rtu: %1</source>
        <translation>RTU：%1</translation>
    </message>
    <message>
        <source>(hung up)</source>
        <translation>（已挂断）</translation>
    </message>
    <message>
        <source>tcp: %1:%2</source>
        <translation>TCP：%1:%2</translation>
    </message>
    <message>
        <source>requests %1, answers %2 (exceptions %3), dropped %4, bad CRC %5, late %6, wrong baud %7</source>
        <translation>请求 %1，应答 %2（异常 %3），丢弃 %4，CRC 错误 %5，延迟 %6，波特率不符 %7</translation>
    </message>
    <message>
        <source>Commands:
  status                 motors, inputs, outputs, link and traffic
  in N on|off|pulse      drive input N by hand (pulse: on for 50 ms)
  get KEY                show a register (e.g. get motor1.position)
  set KEY VALUE          write a parameter as a client would (e.g. set motor1.speed 600)
  do COMMAND             run a coil command (e.g. do motor1.move, do estop)
  place N MM             put carriage N at MM on its travel by hand
  hangup [MS]            hang up the port; it comes back after MS
  power-cycle [S] [id N] switch the 24 V off for S seconds (default 3), every
                         controller or the one with id N; it comes back with what
                         was saved, positions 0, nothing homed
  help                   this text
  quit                   end the simulator</source>
        <translation>命令：
  status                 电机、输入、输出、连接和通信统计
  in N on|off|pulse      手动控制输入 N（pulse：接通 50 ms）
  get 键名               显示寄存器（例如 get motor1.position）
  set 键名 值            像客户端一样写入参数（例如 set motor1.speed 600）
  do 命令                执行线圈命令（例如 do motor1.move、do estop）
  place N 位置           手动将滑台 N 放到其行程上的指定位置（mm）
  hangup [毫秒]          挂断端口；经过指定毫秒数后恢复
  power-cycle [秒] [id N] 切断 24 V 电源指定秒数（默认 3），作用于所有控制器
                         或 ID 为 N 的控制器；恢复后为已保存的参数，坐标为 0，
                         均未回原点
  help                   显示本帮助
  quit                   退出仿真器</translation>
    </message>
    <message>
        <source>usage: power-cycle [SECONDS] [id N]</source>
        <translation>用法：power-cycle [秒] [id N]</translation>
    </message>
    <message>
        <source>no controller has id %1</source>
        <translation>没有 ID 为 %1 的控制器</translation>
    </message>
    <message>
        <source>id %1: 24 V off for %2 s</source>
        <translation>ID %1：24 V 断电 %2 秒</translation>
    </message>
    <message>
        <source>24 V off for %1 s</source>
        <translation>24 V 断电 %1 秒</translation>
    </message>
</context>
<context>
    <name>stepcom::SimDevice</name>
    <message>
        <source>%1: not a writable parameter</source>
        <translation>%1：不是可写参数</translation>
    </message>
    <message>
        <source>%1: not a command of the map</source>
        <translation>%1：不是寄存器映射中的命令</translation>
    </message>
    <message>
        <source>%1: the device failed</source>
        <translation>%1：设备执行失败</translation>
    </message>
    <message>
        <source>time %1 ms, mode %2, id %3, %4 baud</source>
        <translation>时间 %1 ms，模式 %2，ID %3，波特率 %4</translation>
    </message>
    <message>
        <source>motor %1: position %2, %3, carriage at %4 of %5</source>
        <translation>电机 %1：坐标 %2，%3，滑台位于 %4（行程 %5）</translation>
    </message>
    <message>
        <source>running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>inputs:%1</source>
        <translation>输入:%1</translation>
    </message>
    <message>
        <source>outputs:%1</source>
        <translation>输出:%1</translation>
    </message>
    <message>
        <source>the controller is switched off</source>
        <translation>控制器已断电</translation>
    </message>
    <message>
        <source>24 V off: power returns in %1 ms</source>
        <translation>24 V 已断电：%1 ms 后恢复供电</translation>
    </message>
</context>
<context>
    <name>stepcom::SimHost</name>
    <message>
        <source>--lacks: %1 is no listed register of the map</source>
        <translation>--lacks：%1 不是寄存器表中列出的寄存器</translation>
    </message>
    <message>
        <source>power cycle: 24 V off for %1 s</source>
        <translation>断电重启：24 V 断电 %1 秒</translation>
    </message>
    <message>
        <source>power cycle: 24 V back on</source>
        <translation>断电重启：24 V 已恢复供电</translation>
    </message>
    <message>
        <source>%1: axes.motor%2: the register map has %3 motors</source>
        <translation>%1：axes.motor%2：寄存器表只有 %3 个电机</translation>
    </message>
</context>
<context>
    <name>stepcom::SimRegisters</name>
    <message>
        <source>%1: not a writable parameter of the map</source>
        <translation>%1：不是寄存器映射中的可写参数</translation>
    </message>
</context>
<context>
    <name>stepcom::SimRtuTcpServer</name>
    <message>
        <source>cannot listen for RTU over TCP on %1:%2: %3</source>
        <translation>无法在 %1:%2 上监听 TCP 上的 RTU：%3</translation>
    </message>
</context>
<context>
    <name>stepcom::SimState</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1: not JSON (%2)</source>
        <translation>%1：不是 JSON（%2）</translation>
    </message>
    <message>
        <source>%1: not a simulator state file</source>
        <translation>%1：不是仿真器状态文件</translation>
    </message>
    <message>
        <source>%1: parameter %2 is not a number</source>
        <translation>%1：参数 %2 不是数字</translation>
    </message>
</context>
<context>
    <name>stepcom::SimTcpServer</name>
    <message>
        <source>cannot listen on %1:%2: %3</source>
        <translation>无法在 %1:%2 上监听：%3</translation>
    </message>
</context>
<context>
    <name>stepcom::SimWorker</name>
    <message>
        <source>RTU server: %1</source>
        <translation>RTU 服务器：%1</translation>
    </message>
    <message>
        <source>cannot open the pseudo-terminal: %1</source>
        <translation>无法打开伪终端：%1</translation>
    </message>
    <message>
        <source>cannot re-create the port: %1</source>
        <translation>无法重新创建端口：%1</translation>
    </message>
    <message>
        <source>Modbus RTU on a pseudo-terminal (--pty, --link) is not available on this system (pseudo-terminals are Unix only). Use Modbus TCP instead: stepcom-sim --tcp 5020, then connect StepCom or stepcomctl with --tcp 127.0.0.1:5020; or serve a serial port with --serial, e.g. one end of a com0com virtual port pair (--serial COM10, StepCom on COM11).</source>
        <translation>此系统不支持在伪终端上运行 Modbus RTU（--pty、--link）（伪终端仅在 Unix 上可用）。请改用 Modbus TCP：stepcom-sim --tcp 5020，然后用 --tcp 127.0.0.1:5020 连接 StepCom 或 stepcomctl；或者用 --serial 在串口上提供服务，例如 com0com 虚拟串口对的一端（--serial COM10，StepCom 连接 COM11）。</translation>
    </message>
    <message>
        <source>cannot open the serial port %1: %2</source>
        <translation>无法打开串口 %1：%2</translation>
    </message>
</context>
<context>
    <name>stepcom::StatusDock</name>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>on</source>
        <translation>开 (ON)</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关 (OFF)</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>Inputs and outputs</source>
        <translation>输入与输出</translation>
    </message>
    <message>
        <source>In</source>
        <translation>输入</translation>
    </message>
    <message>
        <source>Out</source>
        <translation>输出</translation>
    </message>
    <message>
        <source>IN%1</source>
        <translation>IN%1</translation>
    </message>
    <message>
        <source>OUT%1</source>
        <translation>OUT%1</translation>
    </message>
</context>
<context>
    <name>stepcom::StatusPollRow</name>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>measuring…</source>
        <translation>正在测量…</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>Status updates: %1</source>
        <translation>状态刷新：%1</translation>
    </message>
    <message>
        <source>&amp;Read the status every:</source>
        <translation>状态读取间隔(&amp;R)：</translation>
    </message>
    <message>
        <source>How often the status is read. Full rate reads again as soon as a cycle ends; the link decides how fast that is.</source>
        <translation>读取状态的频率。“最快”表示一个周期结束后立即再次读取，速度由通信链路决定。</translation>
    </message>
    <message>
        <source>full rate</source>
        <translation>最快</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Achieved:</source>
        <translation>实际刷新率：</translation>
    </message>
    <message>
        <source>Status updates per second actually achieved by the poller (complete read cycles, not the configured rate)</source>
        <translation>实际达到的每秒状态刷新次数（完整读取周期数，而不是设定的频率）</translation>
    </message>
</context>
<context>
    <name>stepcom::StatusRecorder</name>
    <message>
        <source>Recording to “%1” stopped: %2</source>
        <translation>记录到“%1”已停止：%2</translation>
    </message>
    <message>
        <source>Cannot write “%1”: %2</source>
        <translation>无法写入“%1”：%2</translation>
    </message>
    <message>
        <source>Cannot record: no file name given</source>
        <translation>无法记录：未指定文件名</translation>
    </message>
    <message>
        <source>Cannot record to “%1”: %2</source>
        <translation>无法记录到“%1”：%2</translation>
    </message>
</context>
<context>
    <name>stepcom::StepMove</name>
    <message>
        <source>There is no motor %1 (this controller has %2)</source>
        <translation>没有电机 %1（此控制器有 %2 个）</translation>
    </message>
    <message>
        <source>This register map has no single move for motor %1</source>
        <translation>此寄存器表中电机 %1 没有单次运行</translation>
    </message>
    <message>
        <source>Motor %1: the distance or position is not a number</source>
        <translation>电机 %1：距离或位置不是数字</translation>
    </message>
    <message>
        <source>Motor %1: a distance cannot be negative</source>
        <translation>电机 %1：距离不能为负</translation>
    </message>
    <message>
        <source>Not connected: nothing was sent</source>
        <translation>未连接：没有发送任何命令</translation>
    </message>
    <message>
        <source>A step is still running: wait for it to end</source>
        <translation>步进仍在运行：请等待其结束</translation>
    </message>
    <message>
        <source>Motor %1: the step uses the single-move distance and direction, and they hold edits that were not written. Write or revert them first.</source>
        <translation>电机 %1：步进使用单次运行的距离和方向，而它们有尚未写入的修改。请先写入或撤销。</translation>
    </message>
    <message>
        <source>Motor %1 is jogging: let go first</source>
        <translation>电机 %1 正在点动：请先松开</translation>
    </message>
    <message>
        <source>Motor %1 is moving: wait until it ends</source>
        <translation>电机 %1 正在运动：请等待其结束</translation>
    </message>
    <message>
        <source>Motor %1: could not read the position and the single-move values (%2): nothing was moved</source>
        <translation>电机 %1：无法读取位置和单次运行参数（%2）：没有运动</translation>
    </message>
    <message>
        <source>Motor %1 is running: nothing was moved</source>
        <translation>电机 %1 正在运行：没有运动</translation>
    </message>
    <message>
        <source>Motor %1: %2 %3 is outside the position register&apos;s range</source>
        <translation>电机 %1：%2 %3 超出位置寄存器的范围</translation>
    </message>
    <message>
        <source>Motor %1 already stands at %2 %3: nothing to move</source>
        <translation>电机 %1 已在 %2 %3：无需运动</translation>
    </message>
    <message>
        <source>Motor %1: a move of %2 %3 is more than the single move can do (%4 %3)</source>
        <translation>电机 %1：%2 %3 的运动超出单次运行的能力（%4 %3）</translation>
    </message>
    <message>
        <source>the step&apos;s distance and direction could not be written (%1): nothing was moved</source>
        <translation>无法写入步进的距离和方向（%1）：没有运动</translation>
    </message>
    <message>
        <source>the single move was not acknowledged: nothing was moved</source>
        <translation>单次运行未被确认：没有运动</translation>
    </message>
    <message>
        <source>distance %1 %2, direction %3</source>
        <translation>距离 %1 %2，方向 %3</translation>
    </message>
    <message>
        <source>%1. The single move&apos;s own values (%2) could not be put back: not connected. Write them again once the controller answers.</source>
        <translation>%1。单次运行原来的参数（%2）未能恢复：未连接。控制器应答后请重新写入。</translation>
    </message>
    <message>
        <source>%1. The single move&apos;s own values (%2) could not be put back: %3</source>
        <translation>%1。单次运行原来的参数（%2）未能恢复：%3</translation>
    </message>
    <message>
        <source>The single move&apos;s own distance and direction are back (verified).</source>
        <translation>单次运行原来的距离和方向已恢复（已校验）。</translation>
    </message>
</context>
<context>
    <name>stepcom::StepMovePanel</name>
    <message>
        <source>&amp;Step:</source>
        <translation>步长(&amp;S)：</translation>
    </message>
    <message>
        <source>Custom</source>
        <translation>自定义</translation>
    </message>
    <message>
        <source>− Step</source>
        <translation>− 步进</translation>
    </message>
    <message>
        <source>+ Step</source>
        <translation>+ 步进</translation>
    </message>
    <message>
        <source>Move &amp;to:</source>
        <translation>运行到(&amp;T)：</translation>
    </message>
    <message>
        <source>Move to position</source>
        <translation>运行到位置</translation>
    </message>
    <message>
        <source>Steps and move-to use this motor&apos;s single-move distance and direction registers, then write your own values back and verify them. They refuse while those fields hold unwritten edits, and any target beyond the software travel limits.</source>
        <translation>步进和运行到位置会使用此电机的单次运行距离和方向寄存器，结束后写回您原来的值并校验。这些字段有未写入的修改时，或目标超出软件行程限位时，将拒绝运行。</translation>
    </message>
    <message>
        <source>Custom step</source>
        <translation>自定义步长</translation>
    </message>
</context>
<context>
    <name>stepcom::SupportBundle</name>
    <message>
        <source>the profile %1 does not exist</source>
        <translation>参数文件 %1 不存在</translation>
    </message>
    <message>
        <source>%1 is not a zip file (or cannot be read)</source>
        <translation>%1 不是 zip 文件（或无法读取）</translation>
    </message>
    <message>
        <source>the bundle %1 holds no session log</source>
        <translation>支持包 %1 中没有会话日志</translation>
    </message>
    <message>
        <source>%1 is not a StepCom support bundle</source>
        <translation>%1 不是 StepCom 支持包</translation>
    </message>
    <message>
        <source>%1 holds no %2</source>
        <translation>%1 中没有 %2</translation>
    </message>
    <message>
        <source>cannot copy %1 out of %2 into %3</source>
        <translation>无法将 %1 从 %2 复制到 %3</translation>
    </message>
    <message>
        <source>cannot create the zip file (zip error %1)</source>
        <translation>无法创建 zip 文件（zip 错误 %1）</translation>
    </message>
    <message>
        <source>cannot write %1 into the bundle</source>
        <translation>无法将 %1 写入支持包</translation>
    </message>
    <message>
        <source>cannot finish the zip file (zip error %1)</source>
        <translation>无法完成 zip 文件（zip 错误 %1）</translation>
    </message>
    <message>
        <source>cannot create %1: %2</source>
        <translation>无法创建 %1：%2</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
</context>
<context>
    <name>stepcom::SupportBundleDialog</name>
    <message>
        <source>Create support bundle</source>
        <translation>创建支持包</translation>
    </message>
    <message>
        <source>The profile %1 and its checklist</source>
        <translation>参数文件 %1 及其调试清单</translation>
    </message>
    <message>
        <source>No profile is open</source>
        <translation>未打开参数文件</translation>
    </message>
    <message>
        <source>&amp;Save bundle…</source>
        <translation>保存支持包(&amp;S)…</translation>
    </message>
    <message>
        <source>Profile:</source>
        <translation>参数文件：</translation>
    </message>
    <message numerus="yes">
        <source>%n session log(s), %1</source>
        <translation>
            <numerusform>%n 个会话日志，%1</numerusform>
        </translation>
    </message>
    <message>
        <source>Save support bundle</source>
        <translation>保存支持包</translation>
    </message>
    <message>
        <source>Zip files (*.zip)</source>
        <translation>Zip 文件 (*.zip)</translation>
    </message>
    <message>
        <source>Support bundle written: %1 (%2). It holds:</source>
        <translation>已写入支持包：%1（%2）。其中包含：</translation>
    </message>
    <message>
        <source>The support bundle was not written: %1</source>
        <translation>未写入支持包：%1</translation>
    </message>
    <message>
        <source>Session logs of the last days:</source>
        <translation>最近几天的会话日志：</translation>
    </message>
    <message>
        <source>One .zip file to send to support: the session logs (every frame of every connection), the profile and its checklist, the commissioning report of the machine, StepCom&apos;s settings (there are no passwords in them), the versions of StepCom, Qt and the system, and the serial adapters seen. A README inside lists it all.</source>
        <translation>发给技术支持的单个 .zip 文件：会话日志（每次连接的每一帧）、参数文件及其调试清单、整机调试报告、StepCom 的设置（其中没有任何密码）、StepCom、Qt 和操作系统的版本，以及见过的串口适配器。其中的 README 列出全部内容。</translation>
    </message>
    <message>
        <source>Report:</source>
        <translation>报告：</translation>
    </message>
    <message numerus="yes">
        <source>id(s) %1 as last read</source>
        <translation>
            <numerusform>ID %1（最后读取的值）</numerusform>
        </translation>
    </message>
    <message>
        <source>the profile %1</source>
        <translation>参数文件 %1</translation>
    </message>
    <message>
        <source>The support bundle was cancelled: nothing was written.</source>
        <translation>支持包已取消：未写入任何内容。</translation>
    </message>
    <message>
        <source>The commissioning report of the machine</source>
        <translation>整机调试报告</translation>
    </message>
    <message>
        <source>None: no device&apos;s settings were read in this session and no profile goes in</source>
        <translation>无：本次会话未读取任何设备的参数，也没有放入参数文件</translation>
    </message>
</context>
<context>
    <name>stepcom::SwitchReference</name>
    <message>
        <source>the home switch (IN%1) did not come ON within %2 %3 toward it</source>
        <translation>朝原点开关（IN%1）移动 %2 %3 内它未变为 ON</translation>
    </message>
    <message>
        <source>the home switch (IN%1) stayed ON %2 %3 away from it</source>
        <translation>离开原点开关（IN%1）%2 %3 后它仍为 ON</translation>
    </message>
    <message>
        <source>the home switch (IN%1) did not come ON again within %2 creep moves</source>
        <translation>原点开关（IN%1）在 %2 次微动移动内未再次变为 ON</translation>
    </message>
</context>
<context>
    <name>stepcom::TrafficModel</name>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Dir</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>Bytes (hex)</source>
        <translation>字节（十六进制）</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
</context>
<context>
    <name>stepcom::TrafficView</name>
    <message>
        <source>&amp;Pause</source>
        <translation>暂停(&amp;P)</translation>
    </message>
    <message>
        <source>C&amp;lear</source>
        <translation>清除(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>复制(&amp;C)</translation>
    </message>
    <message>
        <source>Save traffic log</source>
        <translation>保存通信报文记录</translation>
    </message>
    <message>
        <source>Text files (*.txt *.log)</source>
        <translation>文本文件 (*.txt *.log)</translation>
    </message>
    <message>
        <source>Could not save %1: %2</source>
        <translation>无法保存 %1：%2</translation>
    </message>
    <message>
        <source>Open log folder</source>
        <translation>打开日志文件夹</translation>
    </message>
    <message>
        <source>Hold the rows still to read them; frames are still kept</source>
        <translation>停止滚动以便阅读；报文仍会接收并保留</translation>
    </message>
    <message>
        <source>Polls</source>
        <translation>轮询</translation>
    </message>
    <message>
        <source>The live status poll: several frames a second</source>
        <translation>实时状态轮询：每秒多帧</translation>
    </message>
    <message>
        <source>Reads</source>
        <translation>读取</translation>
    </message>
    <message>
        <source>Writes</source>
        <translation>写入</translation>
    </message>
    <message>
        <source>Commands</source>
        <translation>命令</translation>
    </message>
    <message>
        <source>Errors</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>Search (text, key or bytes)</source>
        <translation>搜索（文字、参数名或字节）</translation>
    </message>
    <message>
        <source>Search</source>
        <translation>搜索</translation>
    </message>
    <message>
        <source>Copy the selected rows (all rows shown when none are selected)</source>
        <translation>复制选中的行（未选中时复制显示的全部行）</translation>
    </message>
    <message>
        <source>&amp;Save log…</source>
        <translation>保存记录(&amp;S)…</translation>
    </message>
    <message>
        <source>Save the rows shown to a file</source>
        <translation>把显示的行保存到文件</translation>
    </message>
    <message>
        <source>Open log &amp;folder</source>
        <translation>打开日志文件夹(&amp;F)</translation>
    </message>
    <message>
        <source>The session log files: every frame of every connection, with date and time (%1)</source>
        <translation>会话日志文件：每次连接的每一帧，带日期和时间（%1）</translation>
    </message>
    <message>
        <source>Cannot create the log folder %1.</source>
        <translation>无法创建日志文件夹 %1。</translation>
    </message>
    <message>
        <source>No file manager opened %1. The session log files are there.</source>
        <translation>没有文件管理器能打开 %1。会话日志文件就在那里。</translation>
    </message>
    <message>
        <source>Earlier lines</source>
        <translation>更早的日志行</translation>
    </message>
    <message>
        <source>Show the lines of the replayed log before the first one here (scrolling to the top does it too)</source>
        <translation>显示回放日志中此处第一行之前的日志行（滚动到顶部也会加载）</translation>
    </message>
</context>
<context>
    <name>stepcom::Translators</name>
    <message>
        <source>Language of the program: en or zh_CN (default: the system&apos;s, from LANGUAGE, LC_ALL, LC_MESSAGES or LANG).</source>
        <translation>程序语言：en 或 zh_CN（默认：系统语言，取自 LANGUAGE、LC_ALL、LC_MESSAGES 或 LANG）。</translation>
    </message>
    <message>
        <source>language</source>
        <translation>语言</translation>
    </message>
    <message>
        <source>unknown language &apos;%1&apos; (known: %2)</source>
        <translation>未知语言“%1”（可用：%2）</translation>
    </message>
    <message>
        <source>, </source>
        <comment>between the items of a list</comment>
        <translation>、</translation>
    </message>
</context>
<context>
    <name>stepcom::TravelCalibration</name>
    <message>
        <source>commanded distance</source>
        <translation>指令距离</translation>
    </message>
    <message>
        <source>measured distance</source>
        <translation>实测距离</translation>
    </message>
    <message>
        <source>the %1 must be more than 0 %2, found %3</source>
        <translation>%1必须大于 0 %2，实际为 %3</translation>
    </message>
    <message>
        <source>not a number</source>
        <translation>非数字</translation>
    </message>
    <message>
        <source>the %1 %2 %3 is not a distance on a machine</source>
        <translation>%1 %2 %3 不是机器上可能的距离</translation>
    </message>
    <message>
        <source>the current pitch (%1) cannot be corrected: %2</source>
        <translation>当前螺距（%1）无法修正：%2</translation>
    </message>
    <message>
        <source>it must be more than 0</source>
        <translation>它必须大于 0</translation>
    </message>
    <message>
        <source>the distances must be at least 0.001 %1</source>
        <translation>距离至少为 0.001 %1</translation>
    </message>
    <message>
        <source>%1 %2 measured for %3 %2 commanded is off by a factor of %4: that is not a calibration error. Check the microsteps (driver DIP switches and register), the step angle and the pitch, then measure again</source>
        <translation>指令 %3 %2 实测 %1 %2，相差 %4 倍：这不是校准误差。请检查细分（驱动器拨码和寄存器）、步距角和螺距，然后重新测量</translation>
    </message>
    <message>
        <source>the corrected pitch would be %1 %2: %3</source>
        <translation>修正后的螺距将为 %1 %2：%3</translation>
    </message>
</context>
<context>
    <name>stepcom::TravelLimits</name>
    <message>
        <source>motor %1: this register map has no such axis</source>
        <translation>电机 %1：此寄存器表中没有这个轴</translation>
    </message>
    <message>
        <source>motor %1, software travel limit %2: %3</source>
        <translation>电机 %1，软件行程限位 %2：%3</translation>
    </message>
    <message>
        <source>motor %1: the software travel limit min (%2) must be below max (%3)</source>
        <translation>电机 %1：软件行程限位的最小值（%2）必须小于最大值（%3）</translation>
    </message>
    <message>
        <source>motor %1: %2 is not a position</source>
        <translation>电机 %1：%2 不是一个位置</translation>
    </message>
    <message>
        <source>motor %1: %2 is beyond the software travel limit max %3</source>
        <translation>电机 %1：%2 超出软件行程限位最大值 %3</translation>
    </message>
    <message>
        <source>motor %1: %2 is beyond the software travel limit min %3</source>
        <translation>电机 %1：%2 超出软件行程限位最小值 %3</translation>
    </message>
    <message>
        <source>motor %1 is at %2, at or beyond its software travel limit max %3: it may only jog toward −</source>
        <translation>电机 %1 位于 %2，已到达或超出软件行程限位最大值 %3：只能朝 − 方向点动</translation>
    </message>
    <message>
        <source>motor %1 is at %2, at or beyond its software travel limit min %3: it may only jog toward +</source>
        <translation>电机 %1 位于 %2，已到达或超出软件行程限位最小值 %3：只能朝 + 方向点动</translation>
    </message>
    <message>
        <source>motor %1 reached its software travel limit max %2 (polled at %3): stop</source>
        <translation>电机 %1 已到达软件行程限位最大值 %2（轮询位置 %3）：停止</translation>
    </message>
    <message>
        <source>motor %1 reached its software travel limit min %2 (polled at %3): stop</source>
        <translation>电机 %1 已到达软件行程限位最小值 %2（轮询位置 %3）：停止</translation>
    </message>
    <message>
        <source>up to %1 beyond a software limit at %2/s (reaction %3 ms: poll %4 ms, read %5 ms, stop %6 ms)</source>
        <translation>以 %2/s 运行时最多越过软件限位 %1（反应时间 %3 ms：轮询 %4 ms，读取 %5 ms，停止 %6 ms）</translation>
    </message>
    <message>
        <source>braking %1 ms included</source>
        <translation>已计入 %1 ms 减速</translation>
    </message>
    <message>
        <source>&quot;travelLimits&quot; must be an object {&quot;motor1&quot;: {&quot;min&quot;: …, &quot;max&quot;: …}}</source>
        <translation>“travelLimits”必须是对象 {&quot;motor1&quot;: {&quot;min&quot;: …, &quot;max&quot;: …}}</translation>
    </message>
    <message>
        <source>&quot;travelLimits&quot;: unknown axis &quot;%1&quot; (this map has motor1 .. motor%2)</source>
        <translation>“travelLimits”：未知的轴“%1”（此寄存器表有 motor1 .. motor%2）</translation>
    </message>
    <message>
        <source>&quot;travelLimits&quot;: &quot;%1&quot; must be an object {&quot;min&quot;: …, &quot;max&quot;: …}</source>
        <translation>“travelLimits”：“%1”必须是对象 {&quot;min&quot;: …, &quot;max&quot;: …}</translation>
    </message>
    <message>
        <source>&quot;travelLimits&quot;: &quot;%1&quot;: unknown field &quot;%2&quot; (allowed: min, max)</source>
        <translation>“travelLimits”：“%1”：未知字段“%2”（允许：min、max）</translation>
    </message>
    <message>
        <source>&quot;travelLimits&quot;: &quot;%1&quot;: &quot;%2&quot; must be a number</source>
        <translation>“travelLimits”：“%1”：“%2”必须是数字</translation>
    </message>
    <message>
        <source>&quot;travelLimits&quot;: &quot;%1&quot; sets neither min nor max</source>
        <translation>“travelLimits”：“%1”既没有设定 min 也没有设定 max</translation>
    </message>
</context>
<context>
    <name>stepcom::TravelLimitsEditor</name>
    <message>
        <source>The saved software travel limits were not used: %1</source>
        <translation>未使用已保存的软件行程限位：%1</translation>
    </message>
    <message>
        <source>How far a jog can overrun a limit is worked out once the speed and pitch are read and the link has answered.</source>
        <translation>读取速度和螺距并且通讯有应答后，将计算点动可能越过限位的距离。</translation>
    </message>
    <message>
        <source>A hold-to-move jog can run past a limit by %1.</source>
        <translation>按住点动时，轴可能越过限位 %1。</translation>
    </message>
    <message>
        <source>Software travel limits</source>
        <translation>软件行程限位</translation>
    </message>
    <message>
        <source>Motor %1</source>
        <translation>电机 %1</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>最小</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>最大</translation>
    </message>
    <message>
        <source>Apply limits</source>
        <translation>应用限位</translation>
    </message>
    <message>
        <source>StepCom&apos;s limits, not the controller&apos;s: a step or move-to beyond them is refused and a jog is stopped when the polled position crosses them. Saved with the connection settings and in profiles. If the link dies during a jog, only the limit switches stop the axis.</source>
        <translation>这是 StepCom 的限位，不是控制器的：超出限位的步进或运行到位置会被拒绝；点动时轮询到的位置越过限位即停止。与连接设置一起保存，也保存在参数文件中。点动时如果通讯中断，只有限位开关能让轴停止。</translation>
    </message>
    <message>
        <source>StepCom&apos;s limits, not the controller&apos;s: if the link dies during a jog, only the limit switches stop the axis.</source>
        <translation>这是 StepCom 的限位，不是控制器的：点动时若通信中断，只有限位开关能停住该轴。</translation>
    </message>
</context>
<context>
    <name>stepcom::TruthWriter</name>
    <message>
        <source>--truth-out: %1: %2</source>
        <translation>--truth-out：%1：%2</translation>
    </message>
</context>
<context>
    <name>stepcom::ValueCheck</name>
    <message>
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
    <message>
        <source>%1: enter a value (%2).</source>
        <translation>%1：请输入数值（%2）。</translation>
    </message>
    <message>
        <source>%1: “%2” is not a number. Allowed: %3.</source>
        <translation>%1：“%2”不是数字。允许范围：%3。</translation>
    </message>
    <message numerus="yes">
        <source>%1: at most %n decimal(s). Allowed: %2.</source>
        <translation>
            <numerusform>%1：最多 %n 位小数。允许范围：%2。</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: %2 is outside the allowed range %3.</source>
        <translation>%1：%2 超出允许范围 %3。</translation>
    </message>
    <message>
        <source>%1: “%2” is not one of %3.</source>
        <translation>%1：“%2”不是 %3 之一。</translation>
    </message>
</context>
<context>
    <name>stepcom::WiringCheck</name>
    <message>
        <source>positive limit</source>
        <translation>正限位</translation>
    </message>
    <message>
        <source>negative limit</source>
        <translation>反限位</translation>
    </message>
    <message>
        <source>home input</source>
        <translation>原点信号</translation>
    </message>
    <message>
        <source>single trigger</source>
        <translation>单次触发运行</translation>
    </message>
    <message>
        <source>forward/reverse trigger</source>
        <translation>正反触发运行</translation>
    </message>
    <message>
        <source>hold-to-jog</source>
        <translation>正反点动运行</translation>
    </message>
    <message>
        <source>fixed-distance trigger</source>
        <translation>按设定距离触发运行</translation>
    </message>
    <message>
        <source>as motor 1&apos;s positive limit</source>
        <translation>作为电机 1 的正限位</translation>
    </message>
    <message>
        <source>as motor 1&apos;s negative limit</source>
        <translation>作为电机 1 的反限位</translation>
    </message>
    <message>
        <source>to start motor 1</source>
        <translation>用于启动电机 1</translation>
    </message>
    <message>
        <source>to stop motor 1 (the next start keeps the direction)</source>
        <translation>用于停止电机 1（下次启动保持原方向）</translation>
    </message>
    <message>
        <source>to stop motor 1 (the next start reverses)</source>
        <translation>用于停止电机 1（下次启动改为反向）</translation>
    </message>
    <message>
        <source>to stop motor 1 (the next start goes forward)</source>
        <translation>用于停止电机 1（下次启动为正向）</translation>
    </message>
    <message>
        <source>to run motor 1 forward</source>
        <translation>用于电机 1 正转</translation>
    </message>
    <message>
        <source>to run motor 1 in reverse</source>
        <translation>用于电机 1 反转</translation>
    </message>
    <message>
        <source>to jog motor 1 forward while it is on</source>
        <translation>用于电机 1 正向点动（输入有效期间运行）</translation>
    </message>
    <message>
        <source>to jog motor 1 in reverse while it is on</source>
        <translation>用于电机 1 反向点动（输入有效期间运行）</translation>
    </message>
    <message>
        <source>to move motor 1 forward by its move distance</source>
        <translation>用于电机 1 按单次运行距离正向运行</translation>
    </message>
    <message>
        <source>to move motor 1 in reverse by its move distance</source>
        <translation>用于电机 1 按单次运行距离反向运行</translation>
    </message>
    <message>
        <source>Motor %1: %2 is both the positive and the negative limit</source>
        <translation>电机 %1：%2 同时被设为正限位和反限位</translation>
    </message>
    <message>
        <source>Motor %1: only the positive limit is set (%2); nothing stops the motor at the negative end</source>
        <translation>电机 %1：只设定了正限位（%2），反向一端没有限位能使电机停止</translation>
    </message>
    <message>
        <source>Motor %1: only the negative limit is set (%2); nothing stops the motor at the positive end</source>
        <translation>电机 %1：只设定了反限位（%2），正向一端没有限位能使电机停止</translation>
    </message>
    <message>
        <source>Motor %1: no home input; homing runs in reverse until the negative limit or a stop and does not zero the position</source>
        <translation>电机 %1：未设定原点信号；回机械零时电机一直反转，直到碰到反限位或收到停止命令，且不会将坐标清零</translation>
    </message>
    <message>
        <source>Motor %1: the home input %2 is the positive limit, but homing runs in reverse, away from it; use the negative limit&apos;s input</source>
        <translation>电机 %1：原点信号 %2 是正限位，但回机械零时电机反转，会远离该开关；请使用反限位的输入口</translation>
    </message>
    <message>
        <source>Motor %1: the home input %2 is neither of its limits; usually the home input is the negative limit (%3)</source>
        <translation>电机 %1：原点信号 %2 不是该电机的任一限位；一般情况下原点与反限位（%3）为同一个输入口</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>motor %1 %2</source>
        <translation>电机 %1 %2</translation>
    </message>
    <message>
        <source>%1 is wired to more than one motor (%2): its switch acts on all of them</source>
        <translation>%1 被分配给多个电机（%2）：该开关会同时作用于这些电机</translation>
    </message>
    <message>
        <source>Motor %1: %2 is set as the %3, but system mode %4 (%5) ignores the limit settings</source>
        <translation>电机 %1：%2 被设为%3，但系统模式 %4（%5）下限位设置无效</translation>
    </message>
    <message>
        <source>Motor %1: %2 is set as the %3, but system mode %4 (%5) ignores the limit settings and uses %2 %6</source>
        <translation>电机 %1：%2 被设为%3，但系统模式 %4（%5）下限位设置无效，此时 %2 %6</translation>
    </message>
</context>
<context>
    <name>stepcom::WiringWarnings</name>
    <message>
        <source>The wiring is not known yet: connect and read the controller.</source>
        <translation>尚不知道接线设置：请连接控制器并读取参数。</translation>
    </message>
    <message>
        <source>No suspicious wiring found.</source>
        <translation>未发现可疑的接线。</translation>
    </message>
</context>
<context>
    <name>stepcom::WriteChangesDialog</name>
    <message>
        <source>Write changes to the controller</source>
        <translation>将更改写入控制器</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Register</source>
        <translation>寄存器</translation>
    </message>
    <message>
        <source>Controller holds</source>
        <translation>控制器中的值</translation>
    </message>
    <message>
        <source>New value</source>
        <translation>新值</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) will be written and then read back to verify. They stay in the controller&apos;s RAM until you save to flash.</source>
        <translation>
            <numerusform>将写入 %n 个参数，然后回读验证。在保存到闪存之前，这些参数只保存在控制器的 RAM 中。</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Write</source>
        <translation>写入(&amp;W)</translation>
    </message>
    <message>
        <source>The pages flag problems in these values:</source>
        <translation>页面已指出这些值中的问题：</translation>
    </message>
    <message>
        <source>&amp;Write anyway</source>
        <translation>仍然写入(&amp;W)</translation>
    </message>
</context>
<context>
    <name>stepcom::WriteReview</name>
    <message>
        <source>Arc: %1</source>
        <translation>圆弧：%1</translation>
    </message>
    <message>
        <source>Line: %1</source>
        <translation>直线：%1</translation>
    </message>
    <message>
        <source>System mode %1 “%2” changes what the inputs IN1-IN4 do, at once, and ignores the limit settings: no limit input stops a motor then.</source>
        <translation>系统模式 %1“%2”会立即改变输入 IN1-IN4 的作用，并忽略限位设置：届时没有限位输入能停止电机。</translation>
    </message>
    <message>
        <source>System mode %1 “%2” changes what the inputs IN1-IN4 do, at once.</source>
        <translation>系统模式 %1“%2”会立即改变输入 IN1-IN4 的作用。</translation>
    </message>
</context>
<context>
    <name>stepcom::XYPlot</name>
    <message>
        <source>Cannot write the picture “%1”.</source>
        <translation>无法写入图片“%1”。</translation>
    </message>
</context>
<context>
    <name>stepcom::XyPicture</name>
    <message>
        <source>start, middle and end point are on one line</source>
        <translation>起点、中间点和终点在一条直线上</translation>
    </message>
    <message>
        <source>the start point is the centre</source>
        <translation>起点与圆心重合</translation>
    </message>
    <message>
        <source>X: motor 1</source>
        <translation>X：电机 1</translation>
    </message>
    <message>
        <source>Y: motor 2</source>
        <translation>Y：电机 2</translation>
    </message>
    <message>
        <source>on</source>
        <translation>开</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>圆弧</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>直线</translation>
    </message>
    <message>
        <source>● start   ○ end   dashed: interpolation off</source>
        <translation>● 起点   ○ 终点   虚线：插补关闭</translation>
    </message>
</context>
<context>
    <name>stepcomctl</name>
    <message>
        <source>What to do.</source>
        <translation>要执行的命令。</translation>
    </message>
    <message>
        <source>list every parameter and command of the register map</source>
        <translation>列出寄存器表中的全部参数和命令</translation>
    </message>
    <message>
        <source>read parameters (all when none are named)</source>
        <translation>读取参数（未指定时读取全部）</translation>
    </message>
    <message>
        <source>write parameters in engineering units, then verify</source>
        <translation>以工程单位写入参数，然后校验</translation>
    </message>
    <message>
        <source>pulse a command coil (e.g. motor1.stop, estop)</source>
        <translation>触发一个命令线圈（例如 motor1.stop、estop）</translation>
    </message>
    <message>
        <source>Commands:</source>
        <translation>命令：</translation>
    </message>
    <message>
        <source>Read and write the parameters of a 2-axis stepper controller over Modbus RTU/TCP.</source>
        <translation>通过 Modbus RTU/TCP 读写两轴步进电机控制器的参数。</translation>
    </message>
    <message>
        <source>compare two profiles, no controller needed; exit 0
same, 1 different, 2 bad file</source>
        <translation>比较两个参数文件，无需控制器；退出码 0 相同，
1 不同，2 文件错误</translation>
    </message>
    <message>
        <source>write the profile&apos;s values that differ, after showing
them and asking (--yes skips the question), then verify;
--include-link also writes device id and baud,
--save-to-flash saves afterwards; the settings it
replaces are saved as a backup first (--no-backup)</source>
        <translation>写入参数文件中不同的值：先列出并询问
（--yes 跳过询问），然后校验；
--include-link 同时写入设备地址和波特率，
--save-to-flash 之后保存到闪存；被替换的设置
先保存为备份（--no-backup 不备份）</translation>
    </message>
    <message>
        <source>pulse a motion command and wait until it ends; print
how it ended (--json), exit 0 only when done or referenced</source>
        <translation>触发一个运动命令并等待其结束；输出
结果（--json），仅在完成或已建立参考点时退出码为 0</translation>
    </message>
    <message>
        <source>move motorN by D or to X (axis units) with its single
move; its own distance and direction are put back and
verified; exit 0 only when it arrived</source>
        <translation>用单次运行将 motorN 运行距离 D 或运行到 X（轴单位）；
之后恢复其原来的距离和方向并校验；
仅在到达时退出码为 0</translation>
    </message>
    <message>
        <source>give the one controller at --id (default 1, as it
leaves the factory) the device id N and check it
answers there; refuses when N is taken or two
controllers answer at --id</source>
        <translation>给 --id（默认 1，即出厂设置）上唯一的那台控制器
分配设备 ID N，并确认它在新 ID 上应答；N 已被占用
或 --id 上有两台控制器应答时拒绝执行</translation>
    </message>
    <message>
        <source>print the live status as one JSON object per line,
until --count samples or Ctrl-C (--interval MS);
with --id 1,2,3 each device in turn, one line a
sample keyed by its id (--json for JSON)</source>
        <translation>以每行一个 JSON 对象输出实时状态，
直到 --count 个样本或 Ctrl-C（--interval MS）；
给出 --id 1,2,3 时依次读取每台设备，每个样本一行，
以其 ID 标注（--json 输出 JSON）</translation>
    </message>
    <message>
        <source>read every setting and save it as a profile file
(--name, --notes; --include-link adds id and baud);
into a folder: one file per --id, &quot;id2 NAME DATE.json&quot;</source>
        <translation>读取全部设置并保存为参数文件
（--name、--notes；--include-link 包括地址和波特率）；
保存到文件夹时每个 --id 一个文件，&quot;id2 名称 日期.json&quot;</translation>
    </message>
    <message>
        <source>write the commissioning report (--name, --notes,
--lang en|zh_CN; --from PROFILE: from a profile
file and its checklist, no controller needed;
--id 1,2,3: every controller in one document)</source>
        <translation>生成调试报告（--name、--notes、
--lang en|zh_CN；--from PROFILE：根据参数文件
及其检查表生成，无需控制器；
--id 1,2,3：所有控制器合为一份文档）</translation>
    </message>
    <message>
        <source>replay a session log (--log FILE or the window&apos;s):
--events, --at TIME [--json], --diff T1 T2; no
controller needed</source>
        <translation>回放会话日志（--log FILE 或窗口写的）：
--events、--at TIME [--json]、--diff T1 T2；
无需控制器</translation>
    </message>
    <message>
        <source>make a support bundle: the session logs of the last
--days N, --profile FILE, the settings, versions, OS
and serial adapters, the machine report (of the
profile, and of the controllers given with --port,
--tcp or --sim and --id), with a README inside</source>
        <translation>生成支持包：最近 --days N 天的会话日志、
--profile FILE、设置、版本、操作系统和串口适配器、
整机报告（参数文件的，以及用 --port、--tcp 或
--sim 和 --id 给出的控制器的），内附 README</translation>
    </message>
    <message>
        <source>success: done, written and verified; diff: the same;
scan: found; move, command --wait: arrived</source>
        <translation>成功：已完成，已写入并校验；diff：相同；
scan：已找到；move、command --wait：已到达</translation>
    </message>
    <message>
        <source>Exit codes (every command):</source>
        <translation>退出码（所有命令）：</translation>
    </message>
    <message>
        <source>Usage:</source>
        <translation>用法：</translation>
    </message>
    <message>
        <source>The link and the other options: stepcomctl --help</source>
        <translation>连接及其他选项：stepcomctl --help</translation>
    </message>
    <message>
        <source>compare the controller with a profile (exit 0 the
same, 1 different, 3 link or device error)</source>
        <translation>将控制器与配置文件比较（退出码 0 相同，
1 不同，3 通信或设备错误）</translation>
    </message>
    <message>
        <source>One command&apos;s help: stepcomctl NAME --help</source>
        <translation>单个命令的帮助：stepcomctl 命令名 --help</translation>
    </message>
    <message>
        <source>find every controller on the line (--port, --rtu-tcp or
--sim; --tcp: ids only) at --bauds, --parity and --ids; a table
(or --json) of id, baud, parity and what answered;
--probe-timeout MS for slow controllers; exit 0 found,
1 none, 2 usage, 3 link error</source>
        <translation>找出线路上的所有控制器（--port、--rtu-tcp 或
--sim；--tcp 只扫描 ID），按 --bauds、--parity 和 --ids 尝试；
以表格（或 --json）列出 ID、波特率、校验和应答的设备；
慢速控制器用 --probe-timeout 毫秒；退出码 0 找到，
1 没有，2 用法错误，3 链路错误</translation>
    </message>
    <message>
        <source>list the serial ports: stable by-id name, adapter
(vendor, product, serial number) and whether another
program holds it; no controller needed</source>
        <translation>列出串口：固定的 by-id 名称、适配器
（厂商、产品、序列号）以及是否被其他程序
占用；无需控制器</translation>
    </message>
    <message>
        <source>the built-in simulator starts from the factory again (id 1, 9600 baud)</source>
        <translation>内置仿真器已恢复出厂状态（ID 1，9600 波特）</translation>
    </message>
    <message>
        <source>hear a line another master (a PLC, an HMI) drives, never
sending a byte: each request paired with its answer and
decoded by the map, a line each as heard (--json), until
Ctrl-C or --seconds N; a summary of frames, pairs, CRC
errors and answer times on stderr (--port, --baud,
--parity; --log FILE keeps it as a session log)</source>
        <translation>监听由另一个主站（PLC、HMI）驱动的线路，从不发送
任何字节：每个请求与其应答配对，按寄存器表解码，
听到即输出一行（--json），直到 Ctrl-C 或 --seconds N；
结束时在标准错误输出帧、配对、CRC 错误和应答时间的
汇总（--port、--baud、--parity；--log FILE 将其保存
为会话日志）</translation>
    </message>
    <message>
        <source>not done: a link or device error, a value not
verified, a file or backup that could not be
written; diff: different; scan: none found; move,
command --wait: stopped elsewhere or not known;
lost-steps: lost or not known; a proof stopped
(Ctrl-C, E-STOP, end of input)</source>
        <translation>未完成：通信或设备错误、值未通过校验、
文件或备份无法写入；diff：不同；
scan：未找到；move、command --wait：
停在别处或结果未知；
lost-steps：丢步或无法判断；验证被中止
（Ctrl-C、急停、输入结束）</translation>
    </message>
    <message>
        <source>nothing was done: a usage or validation error, a bad
file, a write the window asks about without --yes,
an apply not confirmed, a proof refused</source>
        <translation>什么也没做：用法或数值错误、文件有误、
窗口会询问的写入未加 --yes、
apply 未确认、验证被拒绝</translation>
    </message>
    <message>
        <source>diff, scan: a link or device error (their 1 is an
answer); run: the link lost, the controller
restarted, a command not taken; lost-steps,
margin, backlash: the link lost, a restart, a
read or move that failed</source>
        <translation>diff、scan：通信或设备错误（它们的 1
是一种结果）；run：通信中断、控制器
重启、命令未被接受；lost-steps、
margin、backlash：通信中断、重启、
读取或移动失败</translation>
    </message>
    <message>
        <source>prove the axis keeps its steps: the count against the
home switch before and after --cycles K moves of
--distance D out fast and back slowly, and the other
way (docs/proving.md); shown and asked first (--yes);
exit 0 kept, 1 lost, not known or stopped, 2 refused,
3 link, restart or device</source>
        <translation>验证轴不丢步：以原点开关对照计数，比较
--cycles K 次 --distance D 的移动（快速外移、
慢速返回，以及反过来）前后的结果
（docs/proving.md）；先显示并询问（--yes 跳过）；
退出码 0 未丢步，1 丢步、无法判断或被停止，
2 被拒绝，3 通信、重启或设备错误</translation>
    </message>
    <message>
        <source>the lost-step test at each speed --from .. --to in
--step (--accel: the acceleration), lowest first, up
to the first loss; recommends 75 % of the highest kept
and writes it only with --apply; exit 0 searched, 1
stopped or nothing kept to apply, 2 refused, 3 link</source>
        <translation>在 --from .. --to 之间按 --step 取的每个转速
（--accel：加速度）下运行丢步测试，由低到高，
直到第一次丢步；推荐未丢步最高值的 75 %，
仅在 --apply 时写入；退出码 0 已搜索，1 被停止
或没有可写入的未丢步值，2 被拒绝，3 通信错误</translation>
    </message>
    <message>
        <source>the lost motion on reversal with a dial gauge: moves of
--distance D, each followed by &apos;gauge (mm)?&apos; on stderr
and a reading from stdin; exit 0 measured, 1 stopped
(end of input), 2 refused, 3 link</source>
        <translation>用百分表测量反向间隙：每次移动 --distance D，
之后在 stderr 输出 &apos;gauge (mm)?&apos;，
并从 stdin 读取一个读数；退出码 0 已测量，
1 被停止（输入结束），2 被拒绝，3 通信错误</translation>
    </message>
    <message>
        <source>run a machine cycle (a .stepseq file: home, moves, waits
for inputs, outputs, dwells, repeats; docs/sequence.md)
--cycles N times, after showing it and asking (--yes);
each step a line on stderr (--json: JSON lines); Ctrl-C
stops the motors; --check-steps: then the lost-step test
on every axis it moved; exit 0 done (and kept), 1
stopped by the machine (timeout, limit, E-STOP), Ctrl-C
or steps lost, 2 bad file, 3 link, restart or device</source>
        <translation>运行机器循环（.stepseq 文件：回零、移动、等待
输入、输出、停留、重复；docs/sequence.md）
共 --cycles N 次，先显示并询问（--yes 跳过）；
每个步骤在 stderr 输出一行（--json：JSON 行）；Ctrl-C
停止电机；--check-steps：然后对移动过的每根轴
运行丢步测试；退出码 0 完成（且未丢步），1 被机器
停止（超时、限位、急停）、Ctrl-C 或丢步，2 文件
错误，3 通信、重启或设备错误</translation>
    </message>
</context>
</TS>
